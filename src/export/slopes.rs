//! `roughtui export --view slopes`: the scene's curves as CSV, computed and
//! formatted on several threads while the main thread writes.

use std::io::Write;
use std::sync::mpsc;

use rough_model::{Curves, Scene, SceneSpec};

use crate::figure::scene_text::csv_comments;
use crate::figure::{FigureOptions, View};
use crate::physical::csv_number;
use crate::scene::State;

/// The CSV header after the first column, which is named after the swept
/// parameter (`zeta`, `h0_over_e`, `h_rms`, `hurst`, `r_star`).
pub const HEADER: &str = "psi,h_use_over_h0,elastic,plastic,total,persson_elastic";

/// Rows per block: blocks are computed and formatted on worker threads and
/// written in order, so memory stays bounded however many points are asked
/// for (a block's text is ~1 MB).
const BLOCK: usize = 1 << 13;

/// Writes the CSV of `state` at `points` points (both ends included): the
/// scene in `#` lines, then the header and the rows.
///
/// Formatting the numbers costs more than computing them, so both run on
/// every core: worker k takes blocks k, k + T, k + 2T, … and hands each to
/// this thread, which writes them in order while the workers go on, and
/// hands the buffers back for reuse (one channel each way per worker, one
/// block in flight: at most ~3 blocks per worker exist at once).
pub fn write_csv(out: &mut impl Write, state: &State, points: usize) -> anyhow::Result<()> {
    let spec = state.scene_spec(Curves::ALL, points);
    // Fail before the header if the request itself is bad.
    Scene::compute_range(&spec, 0..0)?;
    let opts = FigureOptions {
        points,
        ..FigureOptions::default()
    };
    out.write_all(csv_comments(state, View::Slopes, &opts).as_bytes())?;
    writeln!(out, "{},{HEADER}", state.sweep.axis().field())?;
    let blocks = points.div_ceil(BLOCK);
    let block = |b: usize| b * BLOCK..((b + 1) * BLOCK).min(points);
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get().min(8));
    if threads == 1 || blocks == 1 {
        let mut buf = String::new();
        for b in 0..blocks {
            buf.clear();
            format_rows(&spec, block(b), &mut buf)?;
            out.write_all(buf.as_bytes())?;
        }
    } else {
        let workers = threads.min(blocks);
        std::thread::scope(|scope| -> anyhow::Result<()> {
            let mut done = Vec::with_capacity(workers);
            let mut spare = Vec::with_capacity(workers);
            for k in 0..workers {
                let (tx, rx) = mpsc::sync_channel::<anyhow::Result<String>>(1);
                let (back_tx, back_rx) = mpsc::channel::<String>();
                let spec = &spec;
                scope.spawn(move || {
                    for b in (k..blocks).step_by(workers) {
                        let mut buf = back_rx.try_recv().unwrap_or_default();
                        buf.clear();
                        let r = format_rows(spec, block(b), &mut buf).map(|()| buf);
                        // The writer has stopped (an error): stop too.
                        if tx.send(r).is_err() {
                            return;
                        }
                    }
                });
                done.push(rx);
                spare.push(back_tx);
            }
            for b in 0..blocks {
                let buf = done[b % workers]
                    .recv()
                    .map_err(|_| anyhow::anyhow!("a formatting thread stopped"))??;
                out.write_all(buf.as_bytes())?;
                // A worker that has finished no longer takes buffers back.
                let _ = spare[b % workers].send(buf);
            }
            Ok(())
        })?;
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
