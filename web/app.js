// The class page's glue: the join form, then xterm.js on a WebSocket to
// /ws that carries the same explorer session an SSH student gets.
// Client to server: binary messages are the terminal's input (keys as a
// terminal sends them), a text message "resize COLS ROWS" the window's
// size. Server to client: binary messages are the terminal's output; the
// close frame's reason says why the session ended or was refused.
"use strict";

(function () {
  const form = document.getElementById("join");
  const nameIn = document.getElementById("name");
  const codeIn = document.getElementById("code");
  const why = document.getElementById("why");
  const box = document.getElementById("term");
  const ended = document.getElementById("ended");
  const endWhy = document.getElementById("endwhy");
  const params = new URLSearchParams(location.search);
  nameIn.value = params.get("name") || localStorage.getItem("roughtui-name") || "";
  codeIn.value = params.get("code") || "";

  // A font that gives a phone at least 40 columns (the compact screen),
  // and a laptop the full explorer.
  function fontSize() {
    const w = window.innerWidth;
    // (Monospace cells are about 0.6 em wide; 44 leaves room for the
    // scrollbar and rounding.)
    return Math.max(7, Math.min(15, Math.floor(w / 44 / 0.6)));
  }

  let term = null;
  let fit = null;
  let sock = null;

  function send(text) {
    if (sock && sock.readyState === WebSocket.OPEN) {
      sock.send(text);
    }
  }

  function sendSize() {
    if (!term) {
      return;
    }
    term.options.fontSize = fontSize();
    fit.fit();
    send("resize " + term.cols + " " + term.rows);
  }

  function showForm(reason) {
    box.style.display = "none";
    ended.style.display = "none";
    form.style.display = "block";
    why.textContent = reason || "";
    if (term) {
      term.dispose();
      term = null;
    }
  }

  function join(name, code) {
    form.style.display = "none";
    ended.style.display = "none";
    box.style.display = "block";
    localStorage.setItem("roughtui-name", name);
    term = new Terminal({
      screenReaderMode: true,
      cursorBlink: false,
      fontSize: fontSize(),
      scrollback: 1000,
      theme: { background: "#101014" },
    });
    fit = new FitAddon.FitAddon();
    term.loadAddon(fit);
    term.open(box);
    fit.fit();
    const q = new URLSearchParams({
      name: name,
      code: code,
      cols: String(term.cols),
      rows: String(term.rows),
    });
    const scheme = location.protocol === "https:" ? "wss://" : "ws://";
    sock = new WebSocket(scheme + location.host + "/ws?" + q.toString());
    sock.binaryType = "arraybuffer";
    let opened = false;
    const encoder = new TextEncoder();
    sock.onopen = function () {
      opened = true;
      term.focus();
    };
    sock.onmessage = function (ev) {
      if (typeof ev.data !== "string") {
        term.write(new Uint8Array(ev.data));
      }
    };
    sock.onclose = function (ev) {
      // 4000-4999: refused before the explorer started (a wrong code, a
      // full class): back to the form with the reason.
      if (ev.code >= 4000 && ev.code < 5000) {
        showForm(ev.reason);
        return;
      }
      endWhy.textContent = ev.reason || (opened ? "the session ended" : "cannot reach the class");
      ended.style.display = "block";
    };
    term.onData(function (d) {
      send(encoder.encode(d));
    });
    term.onBinary(function (d) {
      const b = new Uint8Array(d.length);
      for (let i = 0; i < d.length; i++) {
        b[i] = d.charCodeAt(i) & 255;
      }
      send(b);
    });
  }

  window.addEventListener("resize", sendSize);
  form.addEventListener("submit", function (ev) {
    ev.preventDefault();
    const name = nameIn.value.trim();
    if (!name) {
      why.textContent = "a name, please: the class list shows it";
      return;
    }
    join(name, codeIn.value.trim());
  });
  document.getElementById("again").addEventListener("click", function (ev) {
    ev.preventDefault();
    showForm("");
  });
  // ?name=NAME (and &code=WORD) joins at once.
  if (params.get("name")) {
    join(params.get("name").trim(), (params.get("code") || "").trim());
  }
})();
