//! A phone in the class, tested as a student meets it: headless Chromium
//! in mobile emulation (390×844 CSS pixels, touch, no keyboard) taps
//! through a poll of the shipped lesson while an OpenSSH lecturer in tmux
//! leads. The picture is the view drawn by the export's SVG code; before
//! the reveal it leaves out the curves that would answer the poll; the
//! reveal and the answers' histogram come; a reload takes the same seat.
//! A name that looks like HTML stays text. A phone on its side (844×390)
//! gets the same layout, the picture beside the poll, the question, the
//! answer button, the whole picture and the reveal in view without
//! scrolling; a tablet (800×1280, touch) the terminal fitted to 80 columns
//! with on-screen keys.
//!
//! `ROUGHTUI_SHOTS=DIR` keeps the screenshots (the question, the answer,
//! the reveal) in DIR. Skipped (with a note) without chromium,
//! chromium-driver, selenium, ssh or tmux, unless ROUGHTUI_REQUIRE_* say
//! otherwise (`.ci/run`).

mod common;

use common::browser::{have_browser, web_port, Browsers};
use common::lecture::{csvs, lecturer_key, lecturer_line};
use common::room::Room;
use common::serve::{have_ssh, Server};
use common::tmux::have_tmux;

const CODE: &str = "granite";

/// The phone page's element `id`'s text.
fn text_of(id: &str) -> String {
    format!("return document.getElementById('{id}').textContent")
}

/// Whether the element `selector` is on screen whole, without scrolling.
fn in_view(selector: &str) -> String {
    format!(
        "const r = document.querySelector(\"{selector}\").getBoundingClientRect(); \
         return String(window.scrollY === 0 && r.height > 0 && r.top >= 0 && \
         r.bottom <= window.innerHeight && r.right <= window.innerWidth)"
    )
}

/// Whether the picture draws a curve in `colour` (`#0000FF`: plastic).
fn draws(colour: &str) -> String {
    format!(
        "return String(Array.from(document.querySelectorAll('#pic polyline, #pic path'))\
         .some(e => e.getAttribute('stroke') === '{colour}'))"
    )
}

#[test]
fn a_phone_taps_through_a_lesson_poll() {
    if !(have_browser() && have_ssh() && have_tmux()) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let key = lecturer_key(dir.path());
    let keys = key.with_extension("pub");
    let lesson = concat!(env!("CARGO_MANIFEST_DIR"), "/lessons/paper.ron");
    let srv = Server::start(
        dir.path(),
        &[
            "--lecturer-keys",
            keys.to_str().unwrap(),
            "--class-code",
            CODE,
            "--web",
            "127.0.0.1:0",
            "--lesson",
            lesson,
        ],
    );
    let port = web_port(&srv);
    let room = Room::new("phone", (100, 30));
    room.open("lect", &lecturer_line(&srv, &key));
    room.wait("lect", "the lecturer", 30, |s| s.contains("step 1/8"));
    let shots = std::env::var_os("ROUGHTUI_SHOTS").map(std::path::PathBuf::from);
    let mut b = Browsers::start();
    let shot = |b: &mut Browsers, what: &str| {
        if let Some(d) = &shots {
            b.shot("pia", &d.join(format!("phone-{what}.png")));
        }
    };
    // A name that reads as HTML joins as text.
    let name = "<i>pia</i>";
    let url = format!("http://127.0.0.1:{port}/?code={CODE}&name=%3Ci%3Epia%3C%2Fi%3E");
    b.open_phone("pia", &url, (390, 844));
    b.wait_js("pia", "the name", 30, &text_of("who"), |t| t == name);
    let html = b.js_text(
        "pia",
        "return String(document.querySelectorAll('#phone i').length)",
    );
    assert_eq!(html, "0", "the name went in as HTML");
    // Neither the code nor the name stays in the address bar.
    let href = b.js_text("pia", "return location.href");
    assert_eq!(href, format!("http://127.0.0.1:{port}/"));
    // A phone on its side, and a tablet.
    let side = format!("http://127.0.0.1:{port}/?code={CODE}&name=lan");
    b.open_phone("lan", &side, (844, 390));
    b.wait_js("lan", "the phone on its side", 30, &text_of("who"), |t| {
        t == "lan"
    });
    let tablet = format!("http://127.0.0.1:{port}/?code={CODE}&name=tab");
    b.open_phone("tab", &tablet, (800, 1280));
    b.wait_js(
        "tab",
        "the tablet's terminal",
        30,
        "return String(document.getElementById('phone').hidden && \
         !document.getElementById('keys').hidden && \
         !!document.querySelector('.xterm-accessibility-tree'))",
        |t| t == "true",
    );
    // 80 columns of the terminal fit the tablet's width.
    let cols = b.wait_js(
        "tab",
        "the tablet's first screen",
        30,
        "const t = document.querySelector('.xterm-accessibility-tree'); \
         return t ? String(Math.max(...Array.from(t.children).map(r => r.textContent.length))) : '0'",
        |t| t.parse::<u32>().is_ok_and(|n| n >= 80),
    );
    assert!(cols.parse::<u32>().unwrap() >= 80, "{cols}");
    room.wait("lect", "the phones and the tablet in the class", 20, |s| {
        s.contains("3 students · 3 following")
    });
    // Step 3 asks fig. 2's poll, a prediction.
    room.keys("lect", &["n", "n"]);
    b.wait_js("pia", "step 3", 20, &text_of("step"), |t| {
        t.starts_with("step 3/8")
    });
    room.keys("lect", &["v"]);
    b.wait_js("pia", "the question", 20, &text_of("question"), |t| {
        t == "Predict: where does the plastic share pass ½?"
    });
    // Nothing on the phone answers it: no plastic or total curve, no
    // value at the marker, no claim.
    assert_eq!(b.js_text("pia", &draws("#0000FF")), "false");
    assert_eq!(b.js_text("pia", &draws("#FF0000")), "false");
    let page = b.js_text("pia", "return document.getElementById('phone').innerText");
    assert!(page.contains("plastic: after the reveal"), "{page}");
    assert!(!page.contains("321") && !page.contains("0.523"), "{page}");
    shot(&mut b, "question");
    // On its side: the question, the marker's buttons, the answer and the
    // whole picture in view.
    b.wait_js(
        "lan",
        "the question on its side",
        20,
        &text_of("question"),
        |t| t.starts_with("Predict:"),
    );
    for sel in [
        "#question",
        "#pic",
        "#value",
        "[aria-label='more']",
        "[aria-label='answer']",
    ] {
        assert_eq!(b.js_text("lan", &in_view(sel)), "true", "{sel} on its side");
    }
    if let Some(d) = &shots {
        b.shot("lan", &d.join("phone-side-question.png"));
        b.shot("tab", &d.join("tablet-question.png"));
    }
    // Tapping: the marker two steps up and one fine, then the answer.
    let mut value = b.js_text("pia", &text_of("value"));
    assert_eq!(value, "ζ = 128");
    for button in ["more", "more", "more, fine"] {
        b.tap("pia", button);
        let was = value.clone();
        value = b.wait_js("pia", button, 20, &text_of("value"), |t| t != was);
    }
    assert_eq!(value, "ζ = 335");
    b.tap("pia", "answer");
    let answered = b.wait_js("pia", "the answer", 20, &text_of("answer"), |t| {
        t.starts_with("you answered")
    });
    assert!(answered.contains(&value), "{answered} / {value}");
    room.wait("lect", "1/3 answered", 20, |s| s.contains("1/3 answered"));
    shot(&mut b, "answered");
    // The reveal: the model's value, the miss, and the curves back.
    room.keys("lect", &["v"]);
    b.wait_js("pia", "the reveal", 20, &text_of("reveal"), |t| {
        t == "the model: ζ = 321.5"
    });
    let off = b.js_text("pia", &text_of("off"));
    assert_eq!(off, "your answer: 4.2 % high");
    b.wait_js("pia", "the plastic curve", 20, &draws("#0000FF"), |t| {
        t == "true"
    });
    // The answers' histogram for everyone.
    room.keys("lect", &["d"]);
    b.wait_js("pia", "the histogram", 20, &text_of("histcount"), |t| {
        t.starts_with("ζ = 321.5 · 1 answer")
    });
    shot(&mut b, "reveal");
    b.wait_js(
        "lan",
        "the reveal on its side",
        20,
        &text_of("reveal"),
        |t| t == "the model: ζ = 321.5",
    );
    for sel in ["#poll", "#pic"] {
        assert_eq!(b.js_text("lan", &in_view(sel)), "true", "{sel} on its side");
    }
    if let Some(d) = &shots {
        b.shot("lan", &d.join("phone-side-reveal.png"));
    }
    // A reload takes the same seat: the same name, one row.
    b.js("pia", "location.reload(); return 1");
    b.wait_js("pia", "the seat again", 30, &text_of("status"), |t| {
        t == format!("back in your seat as {name}")
    });
    room.keys("lect", &["w"]);
    let list = room.wait("lect", "the class list", 20, |s| s.contains("phone"));
    assert_eq!(list.matches("<i>pia</i>").count(), 1, "{list}");
    room.keys("lect", &["w"]);
    // The lesson's CSV: one row, the answer tapped.
    let csv = std::fs::read_to_string(&csvs(dir.path())[0]).unwrap();
    let rows: Vec<&str> = csv.lines().filter(|l| l.contains(name)).collect();
    assert_eq!(rows.len(), 1, "{csv}");
    let answer: f64 = rows[0].split(',').nth(5).unwrap().parse().unwrap();
    assert_eq!(format!("{answer:.0}"), "335", "{csv}");
    srv.wait_log("the seat taken again", 20, |l| {
        l.contains("back in the seat it left")
    });
}
