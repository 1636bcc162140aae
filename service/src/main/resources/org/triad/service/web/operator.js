// The operator page: remote-operation requests with their cause and the decisions on them, and every
// robot with its task, plan and live floor map.
"use strict";
(() => {
  const { api, live, el, tokenForm, time } = Triad;
  const robotsBox = document.getElementById("robots");
  const cards = new Map();
  let robotNames = [];
  const msg = document.getElementById("operator-message");

  async function load() {
    try {
      const robots = await api("GET", "/api/robots");
      robotNames = robots.map(r => r.name);
      robots.forEach(showRobot);
      showRequests(await api("GET", "/api/requests"));
      refreshAudit();
      const source = live({
        robot: showRobot,
        requests: r => { showRequests(r); refreshAudit(); },
        task: refreshAudit,
        hello: d => d.robots.forEach(showRobot),
        building: robots => { drawBuilding(robots); robots.forEach(showRobot); },
      });
      loadBuilding();
      source.onopen = () => document.getElementById("connection").textContent = "live";
      source.onerror = () => document.getElementById("connection").textContent = "reconnecting...";
      setInterval(refreshMaps, 300);
      showHealth();
      setInterval(showHealth, 2000);
    } catch (e) {
      if (e.status === 401) {
        const box = document.getElementById("access");
        box.hidden = false;
        box.replaceChildren(el("p", { class: "error" }, "This page needs the operator token."));
        tokenForm(box, () => location.reload());
      } else {
        msg.textContent = e.message;
      }
    }
  }

  // the database's outages (a full disk, a lost connection) and, with several instances, who dispatches
  async function showHealth() {
    try {
      const h = await api("GET", "/api/health");
      const who = h.shared ? (h.dispatching ? "; this instance dispatches" : "; another instance dispatches") : "";
      const line = document.getElementById("database");
      line.textContent = h.database + (h.ok ? ": works" : ": FAILS, retrying") + who;
      line.className = h.ok ? "muted" : "error";
      document.getElementById("outages").replaceChildren(...h.outages.concat(h.lease).map(o => el("li", {}, o)));
    } catch (e) {
      document.getElementById("database").textContent = "the service does not answer: " + e.message;
    }
  }

  function showRequests(requests) {
    const list = document.getElementById("requests");
    document.getElementById("no-requests").hidden = requests.length > 0;
    list.replaceChildren(...requests.map(r => {
      const target = el("select", { class: "reassign-robot" }, el("option", { value: "" }, "any robot"), robotNames.map(n => el("option", { value: n }, n)));
      return el("li", { class: "request", "data-task-id": r.task },
        el("div", {}, el("strong", {}, "#" + r.task + " " + r.call), " on ", r.robot || "no robot", " at ", time(r.raisedAt)),
        el("div", { class: "cause" }, (r.goal ? "goal " + r.goal + ": " : "") + r.reason),
        el("div", {},
          el("button", { class: "retry", onclick: () => act("retry", r.task) }, "Retry"),
          target, el("button", { class: "reassign", onclick: () => act("reassign", r.task, { robot: target.value || null }) }, "Re-assign"),
          el("button", { class: "cancel", onclick: () => api("DELETE", "/api/tasks/" + r.task).catch(e => msg.textContent = e.message) }, "Cancel"),
          el("button", { class: "done", onclick: () => act("done", r.task) }, "Mark done")));
    }));
  }

  function act(action, task, body) {
    msg.textContent = "";
    api("POST", "/api/tasks/" + task + "/" + action, body).catch(e => msg.textContent = e.message);
  }

  function showRobot(r) {
    let card = cards.get(r.name);
    if (!card) {
      card = {
        root: el("div", { class: "robot", "data-robot": r.name }),
        canvas: r.map ? el("canvas", { class: "floor" }) : null,
        info: el("div", {}),
        busy: false,
      };
      card.root.append(el("h2", {}, r.name), card.info);
      if (card.canvas) card.root.append(card.canvas);
      robotsBox.append(card.root);
      cards.set(r.name, card);
    }
    const plan = el("ol", { class: "plan" }, r.plan.map((a, i) => el("li", { class: i + 1 === r.step ? "current" : "" }, a)));
    // gone (its platform says so) and refused robots come back by themselves, not by the operator's button
    const state = r.presence === "gone" || r.presence === "refused" ? r.presence : r.online ? (r.task ? "busy" : "idle") : "offline";
    card.root.dataset.presence = r.presence || "";
    card.info.replaceChildren(
      el("div", {}, el("span", { class: "robot-state" }, state),
        r.task ? [" with ", el("span", { class: "robot-task" }, "#" + r.task + " " + r.call)] : "",
        r.battery ? [" ", el("span", { class: "robot-battery" + (r.battery.charging ? " charging" : "") }, "battery " + Math.round(r.battery.charge) + " %" + (r.battery.charging ? ", charging" : ""))] : "",
        r.presence === "refused" || r.presence === "gone" ? "" : [" ", el("button", { class: r.online ? "offline" : "online", onclick: () => api("POST", "/api/robots/" + r.name + "/" + (r.online ? "offline" : "online")).then(showRobot).catch(e => msg.textContent = e.message) },
          r.online ? "Take offline" : "Put online")]),
      r.offlineReason ? el("div", { class: "robot-offline-reason" }, r.offlineReason) : "",
      r.batteryNote ? el("div", { class: "robot-battery-note" }, r.batteryNote) : "",
      r.plan.length ? plan : el("div", { class: "muted" }, "no plan"));
  }

  // the building's live map, one canvas per map id (a floor): each floor's layout as /api/building gives it
  // (every floor of a building of several, else the first robot's), and every robot on the map its pose names;
  // positions come with the event stream's "building" events
  let layouts = new Map();
  async function loadBuilding() {
    try {
      const b = await api("GET", "/api/building");
      layouts = new Map(Object.entries(b.floors || {}));
      if (layouts.size === 0 && b.layout) layouts.set(b.layoutMap || "", b.layout);
      drawBuilding(b.robots);
    } catch (e) {
      msg.textContent = e.message;
    }
  }

  function drawBuilding(robots) {
    const box = document.getElementById("building");
    const placed = robots.filter(r => r.pose);
    document.getElementById("no-positions").hidden = placed.length > 0;
    const floors = new Map();
    for (const id of layouts.keys()) floors.set(id, []);
    for (const r of placed) {
      const id = r.pose.mapId || "";
      if (!floors.has(id)) floors.set(id, []);
      floors.get(id).push(r);
    }
    for (const [id, rs] of floors) {
      let canvas = [...box.querySelectorAll("canvas")].find(c => c.dataset.map === id);
      if (!canvas) {
        canvas = el("canvas", { class: "floor building-floor", "data-map": id });
        box.append(el("figure", {}, el("figcaption", {}, id ? "map " + id : "map"), canvas));
      }
      const marks = rs.map(r => ({ name: r.name, x: r.pose.x, y: r.pose.y,
        note: [r.presence !== "online" ? r.presence : null, r.battery ? Math.round(r.battery.charge) + " %" : null, r.task ? "#" + r.task : null].filter(x => x).join(", ") }));
      const base = layouts.get(id) || around(marks);
      FloorMap.draw(canvas, Object.assign({}, base, { robots: marks }));
      canvas.dataset.robots = marks.map(m => m.name).sort().join(" ");
      canvas.dataset.updates = String(Number(canvas.dataset.updates || 0) + 1);
    }
  }

  // a floor without a layout: just room around its robots
  function around(marks) {
    const xs = marks.map(m => m.x), ys = marks.map(m => m.y);
    return { time: 0, bounds: { minX: Math.min(...xs) - 5, minY: Math.min(...ys) - 5, maxX: Math.max(...xs) + 5, maxY: Math.max(...ys) + 5 },
      areas: [], walls: [], doors: [], waypoints: [], items: [], people: [] };
  }

  let auditBusy = false;
  function refreshAudit() {
    if (auditBusy) return;
    auditBusy = true;
    api("GET", "/api/audit").then(entries => {
      document.querySelector("#audit tbody").replaceChildren(...entries.slice(0, 200).map(e =>
        el("tr", {}, el("td", {}, new Date(e.at).toLocaleString()), el("td", {}, e.who), el("td", {}, e.what), el("td", {}, e.detail))));
    }).catch(() => {}).finally(() => auditBusy = false);
  }

  async function refreshMaps() {
    if (document.hidden) return;
    for (const [name, card] of cards) {
      if (!card.canvas || card.busy) continue;
      card.busy = true;
      api("GET", "/api/robots/" + name + "/floor").then(m => FloorMap.draw(card.canvas, m)).catch(() => {}).finally(() => card.busy = false);
    }
  }

  load();
})();
