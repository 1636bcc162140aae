// The operator page's doors and lifts (issue #20): each device's last reported state, a fault with its reason.
// Kept apart from operator.js.
"use strict";
(() => {
  const { api, el } = Triad;
  const list = document.getElementById("device-list");
  const none = document.getElementById("no-devices");

  async function refresh() {
    try {
      const devices = await api("GET", "/api/devices");
      none.hidden = devices.length > 0;
      list.replaceChildren(...devices.map(d => el("li", { class: "device" + (d.state === "FAULT" ? " error" : ""), "data-device": d.kind + "/" + d.name,
          "data-state": d.state },
        el("strong", {}, d.kind + " " + d.name), " " + d.state + (d.detail ? " (" + d.detail + ")" : "") + (d.reason ? ": " + d.reason : ""))));
    } catch (e) {
      // without the operator token operator.js asks for it; a service that does not answer shows in its health line
    }
  }

  refresh();
  setInterval(refresh, 2000);
})();
