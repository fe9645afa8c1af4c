//! Solve one load on a surface file and print what it took, for
//! scripts/contact_bench.py (which times Tamaas on the same file).
//!
//! Usage: solve SURFACE.f32 N P_MEAN HARDNESS [TOLERANCE]
//! SURFACE.f32: N × N little-endian float32 heights, row-major, cell side 1,
//! E* = 1. Prints one line: seconds, iterations, residual, area,
//! elastic_area, plastic_area.

use rough_contact::{Boundary, Contact, Options};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    if args.len() < 5 {
        eprintln!("usage: solve SURFACE.f32 N P_MEAN HARDNESS [TOLERANCE]");
        std::process::exit(2);
    }
    let n: usize = args[2].parse()?;
    let p_mean: f64 = args[3].parse()?;
    let hardness: f64 = args[4].parse()?;
    let tolerance: f64 = args.get(5).map(|s| s.parse()).transpose()?.unwrap_or(1e-10);
    let bytes = std::fs::read(&args[1])?;
    let h: Vec<f64> = bytes
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64)
        .collect();
    let t = Instant::now();
    let mut c = Contact::new(h, n, 1.0, 1.0, Boundary::Periodic)?;
    let opts = Options {
        tolerance,
        ..Options::default()
    };
    let r = c.solve(p_mean, hardness, &opts)?;
    let secs = t.elapsed().as_secs_f64();
    println!(
        "{secs:.4} {} {:.3e} {} {} {}",
        r.iterations, r.residual, r.area, r.elastic_area, r.plastic_area
    );
    Ok(())
}
