//! One client's explorer: the same [`tui::session::Session`] as the local
//! terminal, fed by the channel's bytes (decoded by [`input`]) and window
//! changes, and, for a student, by the lecturer's state. It ends on `q` /
//! Ctrl-C, when the client goes, stalls, or idles past `--idle-timeout`.

use std::sync::Arc;

use crossterm::cursor::Hide;
use crossterm::event::{Event, KeyEvent};
use crossterm::terminal::EnterAlternateScreen;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Wrap};
use ratatui::Frame;
use russh::server::Msg;
use russh::{Channel, ChannelMsg};
use std::io::Write;
use tokio::sync::watch;
use tokio::time::{sleep_until, Instant};

use super::auth::Role;
use super::follow::{Effect, Follow, Shown, FOLLOWING};
use super::input::{self, Decoder};
use super::limits::clamp_size;
use super::output::{self, FrameBuf};
use super::stream::Kill;
use super::term::{self, ClientTerm};
use super::Shared;
use crate::tui::app::Message;
use crate::tui::glyphs::Glyphs;
use crate::tui::session::Session;

/// What a shell request hands over.
pub struct Start {
    pub shared: Arc<Shared>,
    pub channel: Channel<Msg>,
    pub conn: russh::server::Handle,
    pub kill: Kill,
    pub role: Role,
    pub size: (u16, u16),
    /// The client's TERM and locale: the session's glyphs and colours.
    pub client: ClientTerm,
}

pub fn spawn(start: Start) {
    tokio::spawn(run(start));
}

/// What a student's picture key says instead of writing on the server.
pub const NO_PICTURE: &str = "no pictures over SSH: s shows the snapshot to copy";

/// A student's snapshot text, shown instead of written to the server's disk.
struct Panel(String);

async fn run(start: Start) {
    let Start {
        shared,
        channel,
        conn,
        kill,
        role,
        size,
        client,
    } = start;
    let (mut read, write) = channel.split();
    let slot = output::spawn(write, conn, kill);
    let buf = FrameBuf::default();
    let mut prelude = Vec::new();
    let _ = crossterm::execute!(prelude, EnterAlternateScreen, Hide);
    let _ = slot.send(prelude).await;

    let (mut caps, why) = client.caps(shared.marker);
    // The server's own NO_COLOR turns colour off for everyone.
    caps.color &= std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty());
    let Ok(mut ex) = Session::new(buf.clone(), shared.state.clone(), caps.theme(), size) else {
        return;
    };
    // The first screen's line on switching the drawing, until the first
    // key or HINT_FOR.
    let mut hint = Some(term::hint(caps.glyphs, why.as_deref()));
    let hint_until = Instant::now() + term::HINT_FOR;
    let mut lecturer = shared.follow.subscribe();
    let mut follow = Follow::start(lecturer.borrow_and_update().is_some());
    let is_lecturer = role == Role::Lecturer;
    ex.app.student = !is_lecturer;
    ex.app.lecturer_keys = shared.lecturer_keys.any();
    if is_lecturer {
        shared.lecturer_joined(&mut ex.app);
    } else if follow.following() {
        catch_up(&mut ex, &lecturer.borrow());
        ex.app.set_status(FOLLOWING, false);
    }
    let mut decoder = Decoder::new();
    let mut panel: Option<Panel> = None;
    let idle = shared.idle_timeout;
    let mut deadline = Instant::now() + idle;
    let mut dirty = true;

    loop {
        tokio::select! {
            msg = read.wait() => {
                let Some(msg) = msg else { break };
                match msg {
                    ChannelMsg::Data { data } => {
                        deadline = Instant::now() + idle;
                        let events = decoder.feed(&data[..data.len().min(input::MAX_READ)]);
                        for ev in events {
                            let key = match ev {
                                Event::Key(k) => k,
                                // The terminal's answer to Ctrl-L's question.
                                Event::Resize(w, h) => {
                                    if (w, h) != ex.app.size && ex.update(Message::Resize(w, h)).is_err() {
                                        ex.app.quit = true;
                                        break;
                                    }
                                    dirty = true;
                                    continue;
                                }
                                _ => continue,
                            };
                            if hint.take().is_some() {
                                dirty = true;
                            }
                            if panel.is_some() {
                                // Any key closes the snapshot panel.
                                panel = None;
                                dirty = true;
                                continue;
                            }
                            if ex.message_for(&Event::Key(key)) == Some(Message::Redraw) {
                                decoder.expect_size();
                            }
                            if on_key(&mut ex, &mut follow, &mut panel, role, &lecturer, key) {
                                dirty = true;
                            }
                            if ex.app.quit {
                                break;
                            }
                        }
                        if ex.app.quit {
                            break;
                        }
                        if is_lecturer && dirty {
                            shared.publish(&ex.app);
                        }
                    }
                    ChannelMsg::WindowChange { col_width, row_height, .. } => {
                        let (w, h) = clamp_size(col_width, row_height);
                        if ex.update(Message::Resize(w, h)).is_err() {
                            break;
                        }
                        dirty = true;
                    }
                    ChannelMsg::Eof | ChannelMsg::Close => break,
                    _ => {}
                }
            }
            changed = lecturer.changed(), if !is_lecturer => {
                if changed.is_err() {
                    break;
                }
                let shown = lecturer.borrow_and_update().clone();
                match follow.on_lecturer(shown.is_some()) {
                    Effect::Say(s) => ex.app.set_status(s, false),
                    Effect::Catch => ex.app.set_status(FOLLOWING, false),
                    Effect::None => {}
                }
                if let (true, Some(s)) = (follow.following(), &shown) {
                    // Watching the lecturer counts as activity.
                    deadline = Instant::now() + idle;
                    catch_up(&mut ex, &Some(s.clone()));
                }
                dirty = true;
            }
            () = sleep_until(deadline) => break,
            () = sleep_until(hint_until), if hint.is_some() => {
                hint = None;
                dirty = true;
            }
            permit = slot.reserve(), if dirty => {
                let Ok(permit) = permit else { break };
                let drawn = ex.draw_with(|app, f| {
                    let glyphs = app.theme.glyphs;
                    if let Some(h) = &hint {
                        term::draw_hint(f, h, glyphs);
                    }
                    if let Some(p) = &panel {
                        draw_panel(f, &p.0, glyphs);
                    }
                });
                if drawn.is_err() {
                    break;
                }
                permit.send(buf.take());
                dirty = false;
            }
            () = slot.closed() => break,
        }
    }
    if is_lecturer {
        shared.lecturer_left();
    }
    // Dropping the slot lets the writer restore the client's terminal,
    // send exit status 0 and close the channel.
}

/// Applies one key; whether the screen may have changed.
fn on_key(
    ex: &mut Session<FrameBuf>,
    follow: &mut Follow,
    panel: &mut Option<Panel>,
    role: Role,
    lecturer: &watch::Receiver<Option<Shown>>,
    key: KeyEvent,
) -> bool {
    let Some(msg) = ex.message_for(&Event::Key(key)) else {
        return false;
    };
    if msg == Message::Redraw {
        // Ask the terminal for its size (a client that sends no window
        // change, as Windows' OpenSSH often does not), then repaint; the
        // answer, if any, resizes.
        let _ = ex.writer().write_all(input::ASK_SIZE);
    }
    if msg == Message::Follow {
        match follow.on_follow_key() {
            Effect::Say(s) => ex.app.set_status(s, false),
            Effect::Catch => {
                catch_up(ex, &lecturer.borrow());
                ex.app.set_status(FOLLOWING, false);
            }
            Effect::None => {}
        }
        return true;
    }
    if role == Role::Student {
        if msg == Message::StartSave {
            *panel = Some(Panel(ex.app.state.to_ron()));
            return true;
        }
        if msg == Message::SavePicture {
            // Nothing is written on the server for a student.
            ex.app.set_status(NO_PICTURE, false);
            return true;
        }
        if let Effect::Say(s) = follow.on_message(&msg) {
            // The edit applies first; the status says what happened.
            let ok = ex.update(msg).is_ok();
            ex.app.set_status(s, false);
            return ok;
        }
    }
    ex.update(msg).is_ok()
}

fn catch_up(ex: &mut Session<FrameBuf>, shown: &Option<Shown>) {
    if let Some(s) = shown {
        s.apply(&mut ex.app);
    }
}

fn draw_panel(f: &mut Frame, ron: &str, glyphs: Glyphs) {
    let area = f.area();
    let ron = glyphs.text(ron);
    let lines: Vec<Line> = ron.lines().map(Line::raw).collect();
    // As wide as the longest line where the screen allows, so that a copy
    // gets each line whole.
    let longest = ron.lines().map(|l| l.chars().count()).max().unwrap_or(0);
    let h = (lines.len() as u16 + 2).min(area.height);
    let w = (longest as u16)
        .saturating_add(2)
        .clamp(40, 160)
        .min(area.width);
    let r = Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    );
    f.render_widget(Clear, r);
    f.render_widget(
        Paragraph::new(lines).wrap(Wrap { trim: false }).block(
            Block::default()
                .borders(Borders::ALL)
                .border_set(glyphs.border())
                .title(glyphs.text(" snapshot: copy it into a .ron file · any key closes ")),
        ),
        r,
    );
}
