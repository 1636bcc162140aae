// The operator page's traffic section (issue #21): robots that have waited longer than 30 s for a corridor,
// a door or the lift, with the reason: what they wait for and behind whom. Kept apart from operator.js.
"use strict";
(() => {
  const { api, el } = Triad;
  const list = document.getElementById("traffic-waits");
  const none = document.getElementById("no-traffic-waits");

  async function refresh() {
    try {
      const waits = await api("GET", "/api/traffic");
      none.hidden = waits.length > 0;
      list.replaceChildren(...waits.map(w => el("li", { class: "traffic-wait", "data-robot": w.robot },
        el("strong", {}, w.robot), " waits " + Math.round(w.seconds) + " s: " + w.reason)));
    } catch (e) {
      // without the operator token operator.js asks for it; a service that does not answer shows in its health line
    }
  }

  refresh();
  setInterval(refresh, 2000);
})();
