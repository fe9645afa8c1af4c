//! `roughtui export --view slopes`: the scene's curves as CSV, computed and
//! formatted on several threads.

use std::io::Write;

use rough_model::{Curves, Scene, SceneSpec};

use crate::csv_number;
use crate::snapshot::State;

/// The CSV header, fixed by the command's contract.
pub const HEADER: &str = "x,psi,hardness_ratio,elastic,plastic,total,persson_elastic";

/// Rows per block: each block is split among the threads, computed and
/// formatted there, and written in order, so memory stays bounded however
/// many points are asked for.
const BLOCK: usize = 1 << 14;

/// Writes the CSV of `state` at `points` points (both ends included).
pub fn write_csv(out: &mut impl Write, state: &State, points: usize) -> anyhow::Result<()> {
    let spec = state.scene_spec(Curves::ALL, points);
    // Fail before the header if the request itself is bad.
    Scene::compute_range(&spec, 0..0)?;
    writeln!(out, "{HEADER}")?;
    // Formatting floats costs ~5x computing them: spread both over the cores.
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get().min(8));
    let mut bufs = vec![String::new(); threads];
    let mut start = 0;
    while start < points {
        let end = (start + BLOCK).min(points);
        let per = (end - start).div_ceil(threads);
        if threads == 1 || end - start < 1024 {
            bufs[0].clear();
            format_rows(&spec, start..end, &mut bufs[0])?;
            out.write_all(bufs[0].as_bytes())?;
        } else {
            std::thread::scope(|scope| -> anyhow::Result<()> {
                let jobs: Vec<_> = bufs
                    .iter_mut()
                    .enumerate()
                    .map(|(k, buf)| {
                        let spec = &spec;
                        let lo = (start + k * per).min(end);
                        let hi = (lo + per).min(end);
                        scope.spawn(move || {
                            buf.clear();
                            format_rows(spec, lo..hi, buf)
                        })
                    })
                    .collect();
                for j in jobs {
                    j.join()
                        .map_err(|_| anyhow::anyhow!("a formatting thread panicked"))??;
                }
                Ok(())
            })?;
            for buf in &bufs {
                out.write_all(buf.as_bytes())?;
            }
        }
        start = end;
    }
    out.flush()?;
    Ok(())
}

/// Rows `range` of the scene as CSV lines, numbers in the form of
/// [`csv_number`].
fn format_rows(
    spec: &SceneSpec,
    range: std::ops::Range<usize>,
    buf: &mut String,
) -> anyhow::Result<()> {
    let s = Scene::compute_range(spec, range)?;
    for i in 0..s.x.len() {
        let row = [
            s.x[i],
            s.psi[i],
            s.hardness_ratio[i],
            s.elastic[i],
            s.plastic[i],
            s.total[i],
            s.persson_elastic[i],
        ];
        for (k, v) in row.into_iter().enumerate() {
            if k > 0 {
                buf.push(',');
            }
            csv_number::push(buf, v);
        }
        buf.push('\n');
    }
    Ok(())
}
