// The class page's glue: the join form, then a WebSocket to /ws carrying
// the same explorer session an SSH student gets, drawn by xterm.js (a
// terminal) or, on a phone, as a picture with buttons (phone.js).
// Client to server: binary messages are the terminal's input (keys as a
// terminal sends them), text messages "resize COLS ROWS" (a terminal's
// size) or a phone's command ("view map", "slider zeta", "shape wide").
// Server to client: a text message "seat TOKEN NAME" first (the seat a
// reload takes again, the name the class gave the student), then the
// screen: binary messages for a terminal, text for a phone; the close
// frame's reason says why the session ended or was refused.
// The seat, the code and the layout are kept for this tab only
// (sessionStorage): a reload takes the same seat; the address bar keeps
// neither the code nor the name.
"use strict";

(function () {
  const form = document.getElementById("join");
  const nameIn = document.getElementById("name");
  const codeIn = document.getElementById("code");
  const why = document.getElementById("why");
  const box = document.getElementById("term");
  const keysBar = document.getElementById("keys");
  const ended = document.getElementById("ended");
  const endWhy = document.getElementById("endwhy");
  const params = new URLSearchParams(location.search);
  const kept = window.sessionStorage;
  nameIn.value = params.get("name") || localStorage.getItem("roughtui-name") || "";
  codeIn.value = params.get("code") || kept.getItem("roughtui-code") || "";

  // A touch screen: on-screen keys for what its keyboard lacks. A phone
  // (a touch screen under 600 px on its shorter side): the picture and
  // buttons, upright or on its side; a tablet or a laptop: the terminal.
  const touch = window.matchMedia("(pointer: coarse)").matches;
  const small = Math.min(screen.width, screen.height) < 600;
  function layout() {
    return params.get("layout") || kept.getItem("roughtui-layout") ||
      (touch && small ? "phone" : "term");
  }

  // A font that fits 80 columns where the window allows it (a tablet's
  // terminal), else at least 40 (the compact screen), up to 15 px.
  function fontSize() {
    const w = window.innerWidth;
    // (Monospace cells are about 0.6 em wide; 82 and 44 leave room for
    // the scrollbar and rounding.)
    const fit80 = Math.floor(w / 82 / 0.6);
    if (fit80 >= 9) {
      return Math.min(15, fit80);
    }
    return Math.max(7, Math.min(15, Math.floor(w / 44 / 0.6)));
  }

  let term = null;
  let fit = null;
  let sock = null;
  let phone = false;
  let retry = 0;
  let busy = 0;

  function send(data) {
    if (sock && sock.readyState === WebSocket.OPEN) {
      sock.send(data);
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

  function stopScreen() {
    if (term) {
      term.dispose();
      term = null;
    }
    box.style.display = "none";
    keysBar.hidden = true;
    window.RoughPhone.stop();
  }

  function showForm(reason) {
    stopScreen();
    ended.style.display = "none";
    form.style.display = "block";
    why.textContent = reason || "";
  }

  // The keys a touch screen's keyboard lacks, as a terminal sends them.
  const KEYS = [
    ["←", "\x1b[D", "left"], ["→", "\x1b[C", "right"],
    ["⇧←", "\x1b[1;2D", "shift left"], ["⇧→", "\x1b[1;2C", "shift right"],
    ["↑", "\x1b[A", "up"], ["↓", "\x1b[B", "down"], ["Tab", "\t", "tab"],
    ["⏎", "\r", "enter"], ["Esc", "\x1b", "escape"], ["f", "f", "f"], ["?", "?", "help"],
    ["▦", null, "picture"],
  ];
  function onScreenKeys() {
    keysBar.replaceChildren(...KEYS.map(function (k) {
      const b = document.createElement("button");
      b.type = "button";
      b.textContent = k[0];
      b.setAttribute("aria-label", k[2]);
      b.addEventListener("click", function (ev) {
        ev.preventDefault();
        if (k[1] === null) {
          switchLayout("phone");
          return;
        }
        send(new TextEncoder().encode(k[1]));
      });
      return b;
    }));
    keysBar.hidden = false;
    box.classList.add("keyed");
  }

  function switchLayout(to) {
    kept.setItem("roughtui-layout", to);
    if (sock) {
      sock.onclose = null;
      sock.close();
    }
    join(kept.getItem("roughtui-name") || nameIn.value, kept.getItem("roughtui-code") || "");
  }

  function startTerminal() {
    box.style.display = "block";
    term = new Terminal({
      screenReaderMode: true,
      cursorBlink: false,
      fontSize: fontSize(),
      scrollback: 1000,
      // Text dimmed on the dark ground (the caption) stays readable.
      minimumContrastRatio: 4.5,
      // The dim grey (the caption, hints) lighter than xterm.js's own.
      theme: { background: "#101014", brightBlack: "#a0a0ac" },
    });
    fit = new FitAddon.FitAddon();
    term.loadAddon(fit);
    if (touch) {
      onScreenKeys();
    } else {
      box.classList.remove("keyed");
    }
    term.open(box);
    fit.fit();
    const encoder = new TextEncoder();
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

  function join(name, code) {
    form.style.display = "none";
    ended.style.display = "none";
    stopScreen();
    localStorage.setItem("roughtui-name", name);
    kept.setItem("roughtui-name", name);
    kept.setItem("roughtui-code", code);
    // Neither the code nor the name stays in the address bar (or on the
    // projector's screenshot); a reload joins from this tab's storage.
    if (location.search) {
      history.replaceState(null, "", location.pathname);
    }
    phone = layout() === "phone";
    const q = new URLSearchParams({ name: name, code: code });
    if (phone) {
      q.set("layout", "phone");
    } else {
      startTerminal();
      q.set("cols", String(term.cols));
      q.set("rows", String(term.rows));
    }
    const seat = kept.getItem("roughtui-seat");
    if (seat) {
      q.set("seat", seat);
    }
    const scheme = location.protocol === "https:" ? "wss://" : "ws://";
    sock = new WebSocket(scheme + location.host + "/ws?" + q.toString());
    sock.binaryType = "arraybuffer";
    let opened = false;
    let seated = false;
    sock.onopen = function () {
      opened = true;
      if (phone) {
        window.RoughPhone.start(send);
      } else {
        term.focus();
      }
    };
    sock.onmessage = function (ev) {
      if (typeof ev.data !== "string") {
        if (term) {
          term.write(new Uint8Array(ev.data));
        }
        return;
      }
      if (!seated && ev.data.startsWith("seat ")) {
        // "seat TOKEN NAME": this tab's seat, and the name in the class.
        seated = true;
        retry = 0;
        busy = 0;
        const rest = ev.data.slice(5);
        const sp = rest.indexOf(" ");
        kept.setItem("roughtui-seat", rest.slice(0, sp));
        const who = rest.slice(sp + 1);
        document.title = "roughtui — " + who;
        window.RoughPhone.name(who);
        if (!phone) {
          // Over the terminal's top right corner for a while.
          const badge = document.getElementById("badge");
          badge.textContent = "you are " + who + " in this class";
          badge.hidden = false;
          setTimeout(function () { badge.hidden = true; }, 8000);
        }
        return;
      }
      if (phone) {
        window.RoughPhone.message(ev.data);
      }
    };
    sock.onclose = function (ev) {
      // 4003: the code was not checked (wrong codes from this address
      // came too fast, a classmate's typos or a guesser's): again soon.
      if (ev.code === 4003 && busy < 10) {
        busy += 1;
        showForm(ev.reason + " (trying again …)");
        setTimeout(function () { join(name, code); }, 700 + 300 * busy);
        return;
      }
      // 4000-4999: refused before the explorer started (a wrong code, a
      // full class): back to the form with the reason.
      if (ev.code >= 4000 && ev.code < 5000) {
        kept.removeItem("roughtui-seat");
        showForm(ev.reason);
        return;
      }
      // Dropped without a word (the network, a phone asleep): back to
      // the same seat, a little later each time.
      if (ev.code === 1006 && seated && retry < 8) {
        retry += 1;
        endWhy.textContent = "connection lost: joining again …";
        ended.style.display = "block";
        setTimeout(function () { join(name, code); }, 500 * retry);
        return;
      }
      endWhy.textContent = ev.reason || (opened ? "the session ended" : "cannot reach the class");
      ended.style.display = "block";
    };
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
  document.getElementById("toterm").addEventListener("click", function () {
    switchLayout("term");
  });
  // ?name=NAME (and &code=WORD) joins at once; so does a reload of a tab
  // that held a seat.
  if (params.get("name")) {
    join(params.get("name").trim(), (params.get("code") || "").trim());
  } else if (kept.getItem("roughtui-seat") && kept.getItem("roughtui-name")) {
    join(kept.getItem("roughtui-name"), kept.getItem("roughtui-code") || "");
  }
})();
