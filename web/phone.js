// The phone's page: the session drawn as a picture and text, not cells.
// Each message from the server is text: one line of JSON (the scene, the
// lesson's step, the caption, the claims or the poll, the status, the
// view and the slider, the legend, the answers' histogram), then, when
// the picture changed, its SVG. Every string goes into the page as text
// (textContent), never as HTML; the SVG is parsed as SVG (DOMParser),
// stripped of anything that could run or fetch, and put in the page.
// The buttons send the keys a terminal would; the view and the slider
// are chosen by text commands ("view map", "slider zeta").
"use strict";

window.RoughPhone = (function () {
  const $ = (id) => document.getElementById(id);
  let send = null;

  // Keys as a terminal sends them.
  function key(bytes) {
    if (send) {
      send(new TextEncoder().encode(bytes));
    }
  }

  function command(text) {
    if (send) {
      send(text);
    }
  }

  function text(id, value) {
    const el = $(id);
    el.textContent = value || "";
    return el;
  }

  function show(id, on) {
    $(id).hidden = !on;
  }

  // The SVG as an element of this page: only SVG, nothing that runs.
  function picture(svgText) {
    const doc = new DOMParser().parseFromString(svgText, "image/svg+xml");
    const svg = doc.documentElement;
    if (svg.nodeName !== "svg" || doc.getElementsByTagName("parsererror").length) {
      return;
    }
    for (const el of Array.from(svg.querySelectorAll("script, foreignObject, a, image, use"))) {
      el.remove();
    }
    for (const el of [svg].concat(Array.from(svg.querySelectorAll("*")))) {
      for (const a of Array.from(el.attributes)) {
        if (/^on/i.test(a.name) || /href$/i.test(a.name)) {
          el.removeAttribute(a.name);
        }
      }
    }
    // Scaled to the page's width by its viewBox.
    svg.removeAttribute("width");
    svg.removeAttribute("height");
    const title = svg.querySelector("title");
    $("pic").setAttribute("aria-label", title ? title.textContent : "the view");
    $("pic").replaceChildren(document.importNode(svg, true));
  }

  function legend(entries) {
    const items = (entries || []).map(function (e) {
      const li = document.createElement("li");
      const sample = document.createElement("span");
      sample.className = "sample " + (e[2] === "dashed" ? "dashed" : e[2] === "dot" ? "dot" : "");
      const colour = /^#[0-9A-Fa-f]{6}$/.test(e[1]) ? e[1] : "#888888";
      sample.style.borderTopColor = colour;
      if (e[2] === "dot") {
        sample.style.background = colour;
      }
      const label = document.createElement("span");
      label.textContent = e[0];
      li.append(sample, label);
      return li;
    });
    $("legend").replaceChildren(...items);
  }

  function histogram(h) {
    show("hist", !!h);
    if (!h) {
      return;
    }
    text("histcount", h.count + (h.truth === null ? "" : " · green: the model"));
    text("histlo", h.axis + " " + h.lo);
    text("histhi", h.hi);
    const max = Math.max(1, ...h.counts);
    const bars = h.counts.map(function (c, i) {
      const d = document.createElement("div");
      d.style.height = (100 * c / max) + "%";
      if (i === h.truth) {
        // The model's bar: green, full height (faint) where nobody is.
        d.className = c > 0 ? "truth" : "truth empty";
      }
      d.title = String(c);
      return d;
    });
    $("bars").replaceChildren(...bars);
  }

  let views = "";
  function viewButtons(names, current) {
    const key = names.join(",");
    if (key !== views) {
      views = key;
      $("views").replaceChildren(...names.map(function (n) {
        const b = document.createElement("button");
        b.type = "button";
        b.textContent = n;
        b.setAttribute("aria-label", "view " + n);
        b.addEventListener("click", function () { command("view " + n); });
        return b;
      }));
    }
    for (const b of $("views").children) {
      b.setAttribute("aria-pressed", String(b.textContent === current));
    }
  }

  let sliders = "";
  function sliderChoice(list, slider) {
    const key = list.map((s) => s[0]).join(",");
    const sel = $("sliders");
    if (key !== sliders) {
      sliders = key;
      sel.replaceChildren(...list.map(function (s) {
        const o = document.createElement("option");
        o.value = s[0];
        o.textContent = s[1];
        return o;
      }));
    }
    sel.value = slider.field;
    text("value", slider.symbol + " = " + slider.value);
    text("range", "(" + slider.lo + " … " + slider.hi + ")");
  }

  function update(s) {
    text("scene", s.scene + (s.modified ? " *" : ""));
    text("step", s.step);
    show("step", !!s.step);
    text("caption", s.caption);
    text("claims", s.claims);
    const p = s.poll;
    show("poll", !!p);
    const answering = !!p && !p.revealed;
    if (p) {
      $("poll").className = p.revealed ? "revealed" : "";
      text("question", p.question);
      text("answer", p.answer ? "you answered " + p.answer + (p.revealed ? "" :
        " · answer again to change it · waiting for the reveal") :
        (p.revealed ? "you did not answer" : ""));
      text("reveal", p.revealed ? p.truth : "");
      text("off", p.revealed && p.off ? "your answer: " + p.off : "");
    }
    const row = $("answering").children;
    row[0].hidden = !answering;
    row[1].hidden = !(answering && p.nowhere);
    row[2].hidden = !(p && p.revealed);
    show("answering", !!p);
    const follow = document.querySelector("[aria-label=follow]");
    follow.disabled = !s.lecturer || s.follow !== "own";
    follow.textContent = s.follow === "following" ? "following the lecturer" :
      s.follow === "answering" ? "answer first" : "follow the lecturer";
    const st = text("status", s.status ? s.status.text : "");
    st.className = s.status && s.status.error ? "error" : "";
    viewButtons(s.views, s.view);
    sliderChoice(s.sliders, s.slider);
    legend(s.legend);
    histogram(s.histogram);
    text("readout", (s.readout || []).map((r) => r[0] + " " + r[1]).join(" · ") +
      " (at the marker)");
  }

  // One message: the JSON's line, then the SVG if there is one.
  function message(data) {
    const nl = data.indexOf("\n");
    const json = nl < 0 ? data : data.slice(0, nl);
    update(JSON.parse(json));
    if (nl >= 0) {
      picture(data.slice(nl + 1));
    }
  }

  function shape() {
    return window.innerWidth > window.innerHeight ? "wide" : "upright";
  }

  let lastShape = "";
  function sendShape() {
    const s = shape();
    if (s !== lastShape) {
      lastShape = s;
      command("shape " + s);
    }
  }

  for (const b of document.querySelectorAll("#phone [data-key]")) {
    b.addEventListener("click", function () { key(b.dataset.key); });
  }
  $("sliders").addEventListener("change", function () {
    command("slider " + $("sliders").value);
  });
  window.addEventListener("resize", function () {
    if (send) {
      sendShape();
    }
  });

  return {
    // Starts the page on a session: `sender` sends a key's bytes or a text.
    start: function (sender) {
      send = sender;
      lastShape = "";
      sendShape();
      $("phone").hidden = false;
    },
    stop: function () {
      send = null;
      $("phone").hidden = true;
    },
    message: message,
    name: function (n) { text("who", n); },
  };
})();
