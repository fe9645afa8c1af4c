//! Reads a surface file and prints what roughtui computes from it, with
//! the time taken (a benchmark, not a test; `scripts/surface_bench.py`
//! runs it beside SurfaceTopography on the same file).
//!
//! cargo run --release -p rough-surface --example read_surface -- FILE [--periodic] [--pixel-size M] [--repeat N] [--channel N] [--max-undefined PERCENT]

use std::time::Instant;

use rough_surface::{read, Options};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut opts = Options::default();
    let mut repeat = 1;
    let mut path = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--periodic" => opts.periodic = true,
            "--pixel-size" => opts.pixel_size = it.next().and_then(|v| v.parse().ok()),
            "--repeat" => repeat = it.next().and_then(|v| v.parse().ok()).unwrap_or(1),
            "--channel" => opts.channel = it.next().cloned(),
            "--max-undefined" => {
                opts.max_undefined = it
                    .next()
                    .and_then(|v| v.parse::<f64>().ok())
                    .map(|p| p / 100.0)
            }
            _ => path = Some(std::path::PathBuf::from(a)),
        }
    }
    let path = path.expect("usage: read_surface FILE [--periodic] [--pixel-size M] [--repeat N] [--channel N] [--max-undefined PERCENT]");
    let mut best = f64::INFINITY;
    let mut m = None;
    for _ in 0..repeat {
        let t = Instant::now();
        match read(&path, &opts) {
            Ok(x) => m = Some(x),
            Err(e) => {
                eprintln!("{e}");
                std::process::exit(2);
            }
        }
        best = best.min(t.elapsed().as_secs_f64());
    }
    let m = m.unwrap();
    let zmax = m.table.zeta_max();
    let p = m.table.at_zeta(zmax);
    let t = Instant::now();
    let steps = 100_000;
    let mut acc = 0.0;
    for i in 0..steps {
        acc += m
            .table
            .at_zeta(1.0 + (zmax - 1.0) * i as f64 / steps as f64)
            .m2;
    }
    let per_zeta = t.elapsed().as_secs_f64() / steps as f64;
    println!("{}", m.summary);
    println!(
        "q0 {:e} 1/m, zeta_max {zmax:.6}, {} nodes, {} spectrum points",
        m.table.q0(),
        m.table.nodes().len(),
        m.spectrum.len()
    );
    println!("at zeta_max: m0 {:e} m2 {:e} m4 {:e}", p.m0, p.m2, p.m4);
    println!("read + compute: {:.1} ms (best of {repeat})", best * 1e3);
    println!("one cutoff: {:.0} ns ({acc:e})", per_zeta * 1e9);
}
