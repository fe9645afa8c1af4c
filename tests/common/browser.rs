//! Real browsers for the web tests: headless Chromium driven by selenium
//! (`tests/web/agent.py`, one browser per student), and the server's web
//! port from its console.

use std::io::{BufRead, BufReader, Write};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};
use std::time::{Duration, Instant};

use super::serve::Server;

/// Whether Debian's chromium and chromium-driver and Python's selenium are
/// here; if not, the test says why it skips (and fails instead when
/// `ROUGHTUI_REQUIRE_BROWSER` is set, as in `.ci/run`).
pub fn have_browser() -> bool {
    let ok = ["/usr/bin/chromium", "/usr/bin/chromedriver"]
        .iter()
        .all(|p| std::path::Path::new(p).exists())
        && Command::new("python3")
            .args(["-c", "import selenium"])
            .output()
            .is_ok_and(|o| o.status.success());
    if !ok {
        assert!(
            std::env::var_os("ROUGHTUI_REQUIRE_BROWSER").is_none(),
            "chromium, chromium-driver and selenium are required (ROUGHTUI_REQUIRE_BROWSER is set)"
        );
        eprintln!(
            "no chromium / chromium-driver / selenium: skipping the browser test \
             (apt-get install chromium chromium-driver; pip install selenium)"
        );
    }
    ok
}

/// The server's web port, from its console's `web: listening on` line.
pub fn web_port(srv: &Server) -> u16 {
    let log = srv.wait_log("the web address", 20, |l| l.contains("web: listening on "));
    let line = log
        .lines()
        .find_map(|l| l.strip_prefix("web: listening on "))
        .unwrap();
    line.trim().rsplit(':').next().unwrap().parse().unwrap()
}

/// The browser agent: its browsers are closed when it is dropped.
pub struct Browsers {
    child: Child,
    input: ChildStdin,
    output: BufReader<ChildStdout>,
}

impl Browsers {
    pub fn start() -> Browsers {
        let agent = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/web/agent.py");
        let mut child = Command::new("python3")
            .arg(agent)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .unwrap();
        let input = child.stdin.take().unwrap();
        let output = BufReader::new(child.stdout.take().unwrap());
        Browsers {
            child,
            input,
            output,
        }
    }

    /// One command (a JSON object's fields) and its answer's value.
    fn cmd(&mut self, fields: &str) -> String {
        writeln!(self.input, "{{{fields}}}").unwrap();
        self.input.flush().unwrap();
        let mut line = String::new();
        self.output.read_line(&mut line).unwrap();
        assert!(line.starts_with("{\"ok\": true"), "{fields}: {line}");
        line
    }

    /// A browser window of `w`×`h` pixels on `url`.
    pub fn open(&mut self, name: &str, url: &str, (w, h): (u32, u32)) {
        self.cmd(&format!(
            "\"op\": \"open\", \"name\": {}, \"url\": {}, \"w\": {w}, \"h\": {h}",
            json(name),
            json(url)
        ));
    }

    /// A phone of `w`×`h` CSS pixels on `url`: Chromium's mobile
    /// emulation (touch, no keyboard, an Android browser's agent).
    pub fn open_phone(&mut self, name: &str, url: &str, (w, h): (u32, u32)) {
        self.cmd(&format!(
            "\"op\": \"open\", \"name\": {}, \"url\": {}, \"w\": {w}, \"h\": {h}, \"mobile\": true",
            json(name),
            json(url)
        ));
    }

    /// A finger's tap on the element whose `aria-label` is `label`.
    pub fn tap(&mut self, name: &str, label: &str) {
        self.cmd(&format!(
            "\"op\": \"tap\", \"name\": {}, \"label\": {}",
            json(name),
            json(label)
        ));
    }

    /// A screenshot of the page (PNG) at `path`.
    pub fn shot(&mut self, name: &str, path: &std::path::Path) {
        self.cmd(&format!(
            "\"op\": \"shot\", \"name\": {}, \"path\": {}",
            json(name),
            json(&path.display().to_string())
        ));
    }

    /// A script's value as text (a JSON string's text, else the JSON).
    pub fn js_text(&mut self, name: &str, script: &str) -> String {
        let v = self.js(name, script);
        if v.starts_with('"') {
            unjson(&v)
        } else {
            v
        }
    }

    /// Waits until `script`'s text satisfies `pred`; that text.
    pub fn wait_js(
        &mut self,
        name: &str,
        what: &str,
        secs: u64,
        script: &str,
        pred: impl Fn(&str) -> bool,
    ) -> String {
        let start = Instant::now();
        loop {
            let t = self.js_text(name, script);
            if pred(&t) {
                return t;
            }
            assert!(
                start.elapsed() < Duration::from_secs(secs),
                "timed out waiting for {what} in {name}'s page; it shows:\n{t}"
            );
            std::thread::sleep(Duration::from_millis(100));
        }
    }

    /// The value a script returns, as JSON text.
    pub fn js(&mut self, name: &str, script: &str) -> String {
        let line = self.cmd(&format!(
            "\"op\": \"js\", \"name\": {}, \"script\": {}",
            json(name),
            json(script)
        ));
        value(&line)
    }

    /// The terminal's text, a row a line, as a screen reader reads it.
    pub fn text(&mut self, name: &str) -> String {
        let line = self.cmd(&format!("\"op\": \"text\", \"name\": {}", json(name)));
        unjson(&value(&line))
    }

    pub fn wait(
        &mut self,
        name: &str,
        what: &str,
        secs: u64,
        pred: impl Fn(&str) -> bool,
    ) -> String {
        let start = Instant::now();
        loop {
            let t = self.text(name);
            if pred(&t) {
                return t;
            }
            assert!(
                start.elapsed() < Duration::from_secs(secs),
                "timed out waiting for {what} in {name}'s browser; it shows:\n{t}"
            );
            std::thread::sleep(Duration::from_millis(100));
        }
    }

    /// Keys typed into the terminal: names (`Enter`, `Right`, `S-Right` for
    /// Shift+→) or text.
    pub fn keys(&mut self, name: &str, keys: &[&str]) {
        let list: Vec<String> = keys.iter().map(|k| json(k)).collect();
        self.cmd(&format!(
            "\"op\": \"keys\", \"name\": {}, \"keys\": [{}]",
            json(name),
            list.join(", ")
        ));
    }

    pub fn resize(&mut self, name: &str, (w, h): (u32, u32)) {
        self.cmd(&format!(
            "\"op\": \"resize\", \"name\": {}, \"w\": {w}, \"h\": {h}",
            json(name)
        ));
    }

    /// The tab closes, its WebSocket with it.
    pub fn close(&mut self, name: &str) {
        self.cmd(&format!("\"op\": \"close\", \"name\": {}", json(name)));
    }
}

impl Drop for Browsers {
    fn drop(&mut self) {
        let _ = writeln!(self.input, "{{\"op\": \"quit\"}}");
        let _ = self.input.flush();
        let until = Instant::now() + Duration::from_secs(10);
        while Instant::now() < until {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        let _ = self.child.kill();
    }
}

/// `s` as a JSON string.
pub fn json(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The `value` field of an answer, as JSON text.
fn value(line: &str) -> String {
    let i = line.find("\"value\": ").unwrap() + "\"value\": ".len();
    line[i..].trim_end().trim_end_matches('}').to_string()
}

/// A JSON string's text (`null` is empty).
fn unjson(v: &str) -> String {
    let Some(inner) = v.strip_prefix('"').and_then(|v| v.strip_suffix('"')) else {
        return String::new();
    };
    let mut out = String::new();
    let mut it = inner.chars();
    while let Some(c) = it.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        match it.next() {
            Some('n') => out.push('\n'),
            Some('t') => out.push('\t'),
            Some('u') => {
                let hex: String = it.by_ref().take(4).collect();
                let u = u32::from_str_radix(&hex, 16).unwrap_or(0xfffd);
                // Surrogate pairs: the second half follows.
                if (0xd800..0xdc00).contains(&u) {
                    let _ = it.next();
                    let _ = it.next();
                    let lo: String = it.by_ref().take(4).collect();
                    let lo = u32::from_str_radix(&lo, 16).unwrap_or(0xdc00);
                    let c = 0x10000 + ((u - 0xd800) << 10) + (lo - 0xdc00);
                    out.push(char::from_u32(c).unwrap_or('\u{fffd}'));
                } else {
                    out.push(char::from_u32(u).unwrap_or('\u{fffd}'));
                }
            }
            Some(c) => out.push(c),
            None => {}
        }
    }
    out
}
