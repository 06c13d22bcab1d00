/* assur report: the cycle's animation. The page holds the mechanism drawn at the sketch's pose
   (#cycle-svg) and every element's coordinates at every pose (#cycle-data, strict JSON); this
   script only moves those elements: the slider picks a pose, the button plays the poses in turn
   (looping over a whole turn, to and fro over a stretch). No library, no network. */
(function () {
  "use strict";

  function setAll(svg, tag, attribute, each) {
    var found = svg.querySelectorAll(tag + "[" + attribute + "]");
    for (var i = 0; i < found.length; i += 1) {
      each(found[i], Number(found[i].getAttribute(attribute)));
    }
  }

  function pointsText(flat) {
    var out = [];
    for (var i = 0; i + 1 < flat.length; i += 2) {
      out.push(flat[i] + "," + flat[i + 1]);
    }
    return out.join(" ");
  }

  function start() {
    var source = document.getElementById("cycle-data");
    var svg = document.getElementById("cycle-svg");
    var slider = document.getElementById("cycle-slider");
    var button = document.getElementById("cycle-play");
    var readout = document.getElementById("cycle-readout");
    if (!source || !svg || !slider || !button || !readout) {
      return;
    }
    var data = JSON.parse(source.textContent);
    var shown = -1;
    var timer = null;
    var step = 1;

    function show(frame) {
      var k = Math.max(0, Math.min(data.count - 1, Math.round(frame)));
      if (k === shown) {
        return;
      }
      shown = k;
      setAll(svg, "", "data-link", function (node, i) {
        node.setAttribute("points", pointsText(data.links[i][k]));
      });
      setAll(svg, "circle", "data-pin", function (node, i) {
        node.setAttribute("cx", data.pins[i][2 * k]);
        node.setAttribute("cy", data.pins[i][2 * k + 1]);
      });
      setAll(svg, "text", "data-pin", function (node, i) {
        var r = Number(svg.querySelector("circle[data-pin='" + i + "']").getAttribute("r"));
        node.setAttribute("x", data.pins[i][2 * k] + 1.5 * r);
        node.setAttribute("y", data.pins[i][2 * k + 1] - 1.5 * r);
      });
      setAll(svg, "", "data-slider", function (node, i) {
        var s = data.sliders[i];
        node.setAttribute(
          "transform",
          "translate(" + s[3 * k] + " " + s[3 * k + 1] + ") rotate(" + s[3 * k + 2] + ")"
        );
      });
      setAll(svg, "", "data-guide", function (node, i) {
        var g = data.guides[i];
        node.setAttribute("x1", g[4 * k]);
        node.setAttribute("y1", g[4 * k + 1]);
        node.setAttribute("x2", g[4 * k + 2]);
        node.setAttribute("y2", g[4 * k + 3]);
      });
      readout.textContent = data.readout[k];
      slider.value = String(k);
      svg.setAttribute("data-frame", String(k));
    }

    function advance() {
      var next = shown + step;
      if (next >= data.count || next < 0) {
        if (data.loop) {
          next = (next + data.count) % data.count;
        } else {
          step = -step;
          next = shown + step;
        }
      }
      show(next);
    }

    function stop() {
      if (timer !== null) {
        window.clearInterval(timer);
        timer = null;
      }
      button.textContent = button.getAttribute("data-play");
      button.setAttribute("aria-pressed", "false");
    }

    function play() {
      if (data.count < 2) {
        return;
      }
      timer = window.setInterval(advance, Math.max(16, Math.round(4000 / data.count)));
      button.textContent = button.getAttribute("data-pause");
      button.setAttribute("aria-pressed", "true");
    }

    slider.addEventListener("input", function () {
      show(Number(slider.value));
    });
    button.addEventListener("click", function () {
      if (timer === null) {
        play();
      } else {
        stop();
      }
    });
    shown = -1;
    show(data.sketch);
  }

  if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", start);
  } else {
    start();
  }
})();
