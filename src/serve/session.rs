//! One client's explorer: the same [`tui::session::Session`] as the local
//! terminal, fed by the channel's bytes (decoded by [`input`]) and window
//! changes, and, for a student, by the lecturer's state and the poll; for
//! the lecturer, by the class list. It ends on `q` / Ctrl-C, when the client
//! goes or stalls, when the server stops, or after `--idle-timeout` without
//! a key — only for a session neither lecturing nor following (answering
//! a poll counts as following). When the server ends it, the client's
//! terminal says why on its normal screen.

use std::net::IpAddr;
use std::sync::Arc;
use std::time::Duration;

use crossterm::cursor::Hide;
use crossterm::event::{Event, KeyEvent};
use crossterm::terminal::EnterAlternateScreen;
use russh::server::Msg;
use russh::Channel;
use std::io::Write;
use tokio::time::{sleep_until, Instant};

use super::auth::Role;
use super::follow::{Effect, Follow, CALLED_BACK, FOLLOWING};
use super::frames;
use super::input::{self, Decoder};
use super::output::{self, FrameBuf};
use super::panel::{Key as PanelKey, Panel};
use super::poll;
use super::seat::Seat;
use super::term::{self, ClientTerm};
pub use super::wire::{Input, Render, Wire, WireIn};
use super::Shared;
use crate::class::{self, clean_name, Arrival, Note, Transport};
use crate::tui::app::{Message, Mode};
use crate::tui::session::Session;

/// What a shell request (or a browser's WebSocket) hands over.
pub struct Start {
    pub shared: Arc<Shared>,
    pub wire: Wire,
    pub role: Role,
    pub size: (u16, u16),
    /// The SSH user name (a student's name in the class).
    pub name: String,
    pub addr: IpAddr,
    /// The client's TERM and locale: the session's glyphs and colours.
    pub client: ClientTerm,
    /// How the student reaches the class, and the seat token the page
    /// kept from an earlier session (a reload).
    pub transport: Transport,
    pub token: Option<String>,
}

pub fn spawn(start: Start) {
    tokio::spawn(run(start));
}

/// A session that only says why there is no explorer (the class is full)
/// on the client's normal screen, then ends with status 1.
pub fn refuse(channel: Channel<Msg>, why: String) {
    tokio::spawn(async move {
        let said = async {
            let text = format!("roughtui: {why}\r\n");
            let _ = channel.data(text.as_bytes()).await;
            let _ = channel.exit_status(1).await;
            let _ = channel.eof().await;
            let _ = channel.close().await;
        };
        let _ = tokio::time::timeout(output::STALL, said).await;
    });
}

/// What a student's picture key says instead of writing on the server.
pub const NO_PICTURE: &str = "no pictures over SSH: s shows the snapshot to copy";

/// What a student's terminal says when the lecturer removes them.
pub const REMOVED: &str = "the lecturer removed you from the class";

/// What a session says when a later one takes its seat (a reload).
pub const TAKEN_OVER: &str = "you joined again from another window: this one has left the class";

/// What every client's terminal says when the server stops.
pub const ENDED: &str = "the class has ended";

/// How often the lecturer's open class list updates its idle times.
const LIST_TICK: Duration = Duration::from_secs(1);

async fn run(start: Start) {
    let Start {
        shared,
        wire,
        role,
        size,
        name,
        addr,
        client,
        transport,
        token,
    } = start;
    let Wire {
        input: mut read,
        slot,
        bye,
        via,
        render,
        notes,
    } = wire;
    let phone = render == Render::Phone;
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
    // The contact solver's worker wakes this session (Tick) as it works.
    let solver = Arc::new(tokio::sync::Notify::new());
    let wake = Arc::clone(&solver);
    ex.app.contact.waker = Arc::new(move || wake.notify_one());
    ex.app.contact.engine = Arc::clone(&shared.contact);
    ex.app.contact.sampling = shared.sampling;
    // The first screen's line on switching the drawing, until the first
    // key or HINT_FOR.
    // (Not in a browser: xterm.js draws braille, and M is in the help.)
    let mut hint = via
        .is_empty()
        .then(|| term::hint(caps.glyphs, why.as_deref()));
    let hint_until = Instant::now() + term::HINT_FOR;
    let mut phone_out = phone.then(super::web::phone::Out::default);
    let mut lecturer = shared.follow.subscribe();
    let follow = Follow::start(lecturer.borrow_and_update().is_some());
    let mut s = Seat {
        ex,
        out: buf.clone(),
        shared: Arc::clone(&shared),
        role,
        follow,
        seat: None,
        turn: 0,
        results: Vec::new(),
        poll: None,
        lecturer,
        scene: None,
        pending: false,
    };
    let is_lecturer = s.is_lecturer();
    s.ex.app.student = !is_lecturer;
    s.ex.app.lecturer_keys = shared.lecturer_keys.any();
    s.ex.app.lecturer_here = s.lecturer.borrow().is_some();
    let mut name = clean_name(&name);
    let mut back = false;
    let joined = Instant::now();
    let mut marker = s.marker();
    let mut roster = shared.class.watch_roster();
    let mut polls = shared.class.watch_poll();
    if is_lecturer {
        s.ex.app.class.join_url.clone_from(&shared.join_url);
        shared.lecturer_joined(&mut s.ex.app);
        s.ex.app.class.view = Some(shared.class.view());
        roster.mark_unchanged();
    } else {
        if s.follow.following() {
            s.follow_lecturer();
            s.ex.app.set_status(FOLLOWING, false);
        } else if let Some(lesson) = &shared.lesson {
            // Before the lecturer comes: the lesson's first step, its
            // claims hidden as the lesson says (they may answer a poll).
            let at = class::LessonAt::new(Arc::clone(lesson), 0);
            s.ex.app.class.step = Some(at.line());
        }
        let following = s.follow.following();
        let taken = shared.class.take_seat(&Arrival {
            name: &name,
            addr,
            size,
            marker: marker.name(),
            following,
            via: transport,
            token: token.as_deref(),
        });
        s.seat = Some(taken.id);
        s.turn = taken.turn;
        // Two of one name are told apart (ada, ada-2): the student sees
        // the name the class gave them, a web page keeps the seat.
        name = taken.name;
        if let Some(n) = &notes {
            let _ = n.send(format!("seat {} {name}", taken.token));
        }
        // Over SSH the first screen says it (a page says it itself:
        // followers' first screens stay one frame).
        if let Some(h) = hint.take() {
            hint = Some(format!("{}\n{h}", term::name_line(&name)));
        }
        back = taken.again;
        if back {
            s.ex.app
                .set_status(format!("back in your seat as {name}"), false);
        }
        polls.mark_changed();
    }
    let mut shape = if phone {
        "a phone".to_string()
    } else {
        format!("{}x{}, {}", size.0, size.1, marker.name())
    };
    if back {
        shape.push_str(", back in the seat it left");
    }
    shared.log.line(&format!(
        "join  {name}{} from {addr}{via}, {shape}",
        if is_lecturer { " (lecturer)" } else { "" },
    ));
    let mut decoder = Decoder::new();
    let mut panel: Option<Panel> = None;
    // Bytes for the terminal besides frames (the snapshot panel's).
    let mut raw: Vec<u8> = Vec::new();
    let idle = shared.idle_timeout;
    let mut deadline = Instant::now() + idle;
    let mut list_tick = Instant::now() + LIST_TICK;
    let mut dirty = true;
    let mut ending = shared.ending.subscribe();
    let mut all_follow = shared.all_follow.subscribe();
    let mut removed = shared.class.watch_removed();
    let mut turns = shared.class.watch_turns();
    turns.mark_unchanged();
    if *ending.borrow_and_update() {
        bye.set(ENDED);
        return;
    }

    // The last screen's lines, when the class ends.
    let mut screen: Vec<String> = Vec::new();
    loop {
        // The class list's idle times, the projector's countdown: each second.
        let c = &s.ex.app.class;
        let listing =
            is_lecturer && (s.ex.app.mode == Mode::Class || (c.projector && c.countdown.is_some()));
        // Only a session neither lecturing nor following idles out; the
        // others' idle time starts when they stop.
        let idles = !is_lecturer && !s.follow.in_class();
        if !idles {
            deadline = Instant::now() + idle;
        }
        tokio::select! {
            msg = read.next() => {
                let Some(msg) = msg else { break };
                match msg {
                    WireIn::Data(data) => {
                        deadline = Instant::now() + idle;
                        s.note(Note::Key);
                        let events = decoder.feed(&data[..data.len().min(input::MAX_READ)]);
                        for ev in events {
                            let key = match ev {
                                Event::Key(k) => k,
                                // The terminal's answer to Ctrl-L's question.
                                Event::Resize(w, h) => {
                                    if (w, h) != s.ex.app.size {
                                        if s.update(Message::Resize(w, h)).is_err() {
                                            s.ex.app.quit = true;
                                            break;
                                        }
                                        s.note(Note::Size(w, h));
                                    }
                                    dirty = true;
                                    continue;
                                }
                                _ => continue,
                            };
                            if hint.take().is_some() {
                                dirty = true;
                            }
                            if let Some(p) = &panel {
                                match p.key(key) {
                                    PanelKey::Stay(b) => raw.extend(b),
                                    PanelKey::Close(b) => {
                                        raw.extend(b);
                                        panel = None;
                                        bye.normal_screen(false);
                                        // The explorer whole again.
                                        if s.update(Message::Redraw).is_err() {
                                            s.ex.app.quit = true;
                                            break;
                                        }
                                        dirty = true;
                                    }
                                }
                                continue;
                            }
                            // A phone's page sends its buttons' keys only.
                            if phone
                                && !s
                                    .ex
                                    .message_for(&Event::Key(key))
                                    .is_some_and(super::web::phone::takes)
                            {
                                continue;
                            }
                            // A key is the student's: the explorer catches up.
                            s.sync();
                            if s.ex.message_for(&Event::Key(key)) == Some(Message::Redraw) {
                                decoder.expect_size();
                            }
                            if on_key(&mut s, &mut panel, &mut raw, key) {
                                dirty = true;
                            }
                            // The snapshot printed: a goodbye now stays below it.
                            bye.normal_screen(panel.is_some());
                            if s.ex.app.quit {
                                break;
                            }
                        }
                        if s.ex.app.quit {
                            break;
                        }
                        if s.marker() != marker {
                            marker = s.marker();
                            s.note(Note::Marker(marker.name().into()));
                        }
                        if let Some(id) = s.ex.app.class.remove.take() {
                            let text = match shared.class.remove(id) {
                                Some(who) => {
                                    shared.log.line(&format!("removed {who} (by the lecturer)"));
                                    format!("removed {who}: told so on their terminal")
                                }
                                None => "that student has already left".to_string(),
                            };
                            s.ex.app.set_status(text, false);
                        }
                        if is_lecturer && dirty {
                            shared.publish(&s.ex.app);
                            poll::after_lecturer_keys(&mut s);
                        }
                    }
                    // A phone has no terminal size: its picture's shape.
                    WireIn::Resize(..) if phone => {}
                    WireIn::Resize(w, h) => {
                        if s.update(Message::Resize(w, h)).is_err() {
                            break;
                        }
                        s.note(Note::Size(w, h));
                        dirty = true;
                    }
                    WireIn::Command(c) => {
                        deadline = Instant::now() + idle;
                        s.note(Note::Key);
                        let Some(out) = phone_out.as_mut() else { continue };
                        hint = None;
                        s.sync();
                        for msg in super::web::phone::command(&s.ex.app, out, &c) {
                            on_message(&mut s, msg);
                        }
                        if s.ex.app.quit {
                            break;
                        }
                        dirty = true;
                    }
                }
            }
            changed = s.lecturer.changed(), if !is_lecturer => {
                if changed.is_err() {
                    break;
                }
                let shown = s.lecturer.borrow_and_update().clone();
                s.ex.app.lecturer_here = shown.is_some();
                let e = s.follow.on_lecturer(shown.is_some());
                s.effect(e);
                if s.follow.following() && shown.is_some() {
                    // Watching the lecturer counts as activity.
                    deadline = Instant::now() + idle;
                    s.follow_lecturer();
                }
                dirty = true;
            }
            changed = polls.changed(), if !is_lecturer => {
                if changed.is_err() {
                    break;
                }
                let p = polls.borrow_and_update().clone();
                if poll::on_poll(&mut s, p) {
                    deadline = Instant::now() + idle;
                    dirty = true;
                    // A question or a reveal closes the snapshot's text.
                    if let Some(p) = panel.take() {
                        raw.extend(p.close());
                        bye.normal_screen(false);
                        if s.update(Message::Redraw).is_err() {
                            break;
                        }
                    }
                }
            }
            changed = roster.changed(), if is_lecturer => {
                if changed.is_err() {
                    break;
                }
                roster.mark_unchanged();
                s.ex.app.class.view = Some(shared.class.view());
                dirty = true;
            }
            () = sleep_until(list_tick), if listing => {
                // The open class list's idle times move on.
                s.ex.app.class.view = Some(shared.class.view());
                list_tick = Instant::now() + LIST_TICK;
                dirty = true;
            }
            () = solver.notified(), if s.ex.app.contact.busy() => {
                if s.update(Message::Tick).is_err() {
                    break;
                }
                dirty = true;
            }
            () = sleep_until(deadline), if idles => {
                bye.set(format!(
                    "no key for {}: the session ended (ssh again to come back)",
                    class::duration(idle)
                ));
                break;
            }
            changed = all_follow.changed(), if !is_lecturer => {
                if changed.is_err() {
                    break;
                }
                all_follow.mark_unchanged();
                if s.follow.on_all_follow() == Effect::Catch {
                    s.effect(Effect::Catch);
                    s.ex.app.set_status(CALLED_BACK, false);
                    dirty = true;
                }
            }
            changed = turns.changed(), if !is_lecturer => {
                if changed.is_err() {
                    break;
                }
                let mine = s.seat.and_then(|id| shared.class.turn(id)) == Some(s.turn);
                if !mine {
                    bye.set(TAKEN_OVER);
                    break;
                }
            }
            changed = removed.changed(), if !is_lecturer => {
                if changed.is_err() {
                    break;
                }
                let gone = s.seat.is_some_and(|id| removed.borrow_and_update().contains(&id));
                if gone {
                    bye.set(REMOVED);
                    break;
                }
            }
            _ = ending.changed() => {
                bye.set(ENDED);
                // The terminal keeps the last screen above the goodbye
                // (unless the snapshot is printed there, or it is a phone).
                if panel.is_none() && phone_out.is_none() {
                    screen = super::output::screen_lines(&s.ex.render(|_, _| {}));
                }
                break;
            }
            () = sleep_until(hint_until), if hint.is_some() => {
                hint = None;
                dirty = true;
            }
            permit = slot.reserve(), if dirty || !raw.is_empty() => {
                let Ok(permit) = permit else { break };
                let mut bytes = std::mem::take(&mut raw);
                // While the snapshot is shown, changes wait for its close
                // (which draws the explorer whole).
                if dirty && panel.is_none() {
                    if let Some(out) = phone_out.as_mut() {
                        bytes = super::web::phone::draw(&mut s, out);
                    } else {
                        if frames::draw(&mut s, hint.as_ref()).is_err() {
                            break;
                        }
                        bytes.extend(buf.take());
                    }
                }
                permit.send(bytes);
                dirty = false;
            }
            () = slot.closed() => break,
        }
    }
    let g = s.ex.app.theme.glyphs;
    if let Some(id) = s.seat {
        shared.class.leave(id, s.turn);
        // The terminal keeps who the student was and how their polls went.
        let mut kept = vec![format!("roughtui: you were {name} in the class")];
        kept.extend(s.results.iter().cloned());
        screen.extend(kept.iter().map(|l| g.text(l).into_owned()));
    }
    if !screen.is_empty() {
        bye.keep(screen);
    }
    if is_lecturer {
        shared.lecturer_left();
    }
    shared.log.line(&format!(
        "leave {name}{} from {addr}{via} after {}",
        if is_lecturer { " (lecturer)" } else { "" },
        class::duration(joined.elapsed())
    ));
    // Dropping the slot lets the writer restore the client's terminal,
    // send exit status 0 and close the channel.
}

/// Applies one key; whether the screen may have changed.
fn on_key(s: &mut Seat, panel: &mut Option<Panel>, raw: &mut Vec<u8>, key: KeyEvent) -> bool {
    let Some(msg) = s.ex.message_for(&Event::Key(key)) else {
        return false;
    };
    if msg == Message::Redraw {
        // Ask the terminal for its size (a client that sends no window
        // change, as Windows' OpenSSH often does not), then repaint; the
        // answer, if any, resizes.
        let _ = s.ex.writer().write_all(input::ASK_SIZE);
    }
    if s.role == Role::Student && msg == Message::StartSave {
        let ascii = s.ex.app.theme.glyphs.ascii_text();
        let (p, bytes) = Panel::open(s.ex.app.state.to_ron(), ascii);
        *panel = Some(p);
        raw.extend(bytes);
        return true;
    }
    on_message(s, msg)
}

/// Applies one message of a key (or of a phone's button); whether the
/// screen may have changed.
fn on_message(s: &mut Seat, msg: Message) -> bool {
    match msg {
        Message::Follow => {
            let e = s.follow.on_follow_key();
            s.effect(e);
            return true;
        }
        Message::AllFollow if s.is_lecturer() => {
            s.shared.all_follow.send_modify(|n| *n += 1);
            s.ex.app.set_status("everyone follows you now", false);
            return true;
        }
        Message::Poll
        | Message::SavePoll
        | Message::Answer
        | Message::AnswerNowhere
        | Message::ShareAnswers
        | Message::CancelPoll => {
            poll::on_key(s, msg);
            return true;
        }
        Message::ToggleClass => {
            s.ex.app.class.view = Some(s.shared.class.view());
        }
        _ => {}
    }
    if s.role == Role::Student {
        if msg == Message::SavePicture {
            // Nothing is written on the server for a student.
            s.ex.app.set_status(NO_PICTURE, false);
            return true;
        }
        if let e @ Effect::Say(_) = s.follow.on_message(&msg) {
            // The edit applies first; the status says what happened.
            let ok = s.update(msg).is_ok();
            s.effect(e);
            return ok;
        }
    }
    s.update(msg).is_ok()
}
