//! Prints the default Hurst fit of surface files: band, H, its standard
//! error and the verdict (`cargo run -p rough-surface --example hurst_fit
//! -- [--periodic] FILE…`).

use rough_surface::{read, Options};

fn main() {
    let mut opts = Options::default();
    for a in std::env::args().skip(1) {
        if a == "--periodic" {
            opts.periodic = true;
            continue;
        }
        match read(std::path::Path::new(&a), &opts) {
            Ok(m) => match m.default_fit() {
                Some(f) => println!(
                    "{a}: H {:.4} ± {:.4} over q {:.4e}…{:.4e} 1/m ({} points, rms {:.3} decades, {:.3} unweighted, {:?})",
                    f.hurst,
                    f.hurst_se,
                    f.q_lo,
                    f.q_hi,
                    f.points,
                    f.rms_decades,
                    f.rms_decades_unweighted,
                    f.verdict()
                ),
                None => println!("{a}: no fit"),
            },
            Err(e) => println!("{e}"),
        }
    }
}
