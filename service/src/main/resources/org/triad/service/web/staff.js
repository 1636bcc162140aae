// The staff page: a form per task, built from the OpenAPI document the service derives from the task models.
"use strict";
(() => {
  const { api, live, el, tokenForm, time } = Triad;
  const select = document.getElementById("task-select");
  const argsBox = document.getElementById("args");
  const message = document.getElementById("form-message");
  const tbody = document.querySelector("#tasks tbody");
  const rows = new Map();
  let schemas = {};
  let selected = null;

  async function load() {
    const doc = await (await fetch("/api/openapi.json")).json();
    document.getElementById("title").textContent = doc.info.title;
    schemas = {};
    for (const [name, s] of Object.entries(doc.components.schemas)) {
      if (name.startsWith("Task.")) schemas[name.slice(5)] = s;
    }
    select.replaceChildren(...Object.keys(schemas).map(t => el("option", { value: t }, t)));
    select.onchange = () => form(select.value);
    form(select.value);
    try {
      const tasks = await api("GET", "/api/tasks");
      tasks.reverse().forEach(show);
      live({ task: d => { show(d.task, d.event); if (selected === d.task.id) detail(d.task.id); } });
    } catch (e) {
      if (e.status === 401) askToken();
      else message.textContent = e.message;
    }
  }

  function askToken() {
    const box = document.getElementById("access");
    box.hidden = false;
    box.replaceChildren(el("p", { class: "error" }, "This page needs the submit token."));
    tokenForm(box, () => location.reload());
  }

  function form(task) {
    const s = schemas[task];
    document.getElementById("task-description").textContent = s ? s.description : "";
    argsBox.replaceChildren();
    if (!s) return;
    const props = s.properties.args.properties || {};
    for (const [name, p] of Object.entries(props)) {
      const id = "arg-" + name;
      let input;
      if (p.enum) input = el("select", { id, name }, p.enum.map(v => el("option", { value: v }, v)));
      else if (p.type === "boolean") input = el("input", { id, name, type: "checkbox" });
      else if (p.type === "integer" || p.type === "number") input = el("input", { id, name, type: "number", step: p.type === "integer" ? "1" : "any" });
      else input = el("input", { id, name, type: "text" });
      argsBox.append(el("label", { for: id }, p.description || name), input, el("div", { class: "field-error", id: "error-args." + name }));
    }
  }

  document.getElementById("task-form").addEventListener("submit", async ev => {
    ev.preventDefault();
    const task = select.value;
    const args = {};
    for (const [name, p] of Object.entries(schemas[task].properties.args.properties || {})) {
      const input = document.getElementById("arg-" + name);
      args[name] = p.type === "boolean" ? input.checked : (p.type === "integer" || p.type === "number") && !p.enum ? Number(input.value) : input.value;
    }
    argsBox.querySelectorAll(".field-error").forEach(e => e.textContent = "");
    document.getElementById("error-priority").textContent = "";
    const priority = Number(document.getElementById("task-priority").value || 0);
    try {
      const t = await api("POST", "/api/tasks", { task, args, priority });
      message.textContent = "Task #" + t.id + " queued.";
      message.className = "";
      show(t);
      selected = t.id;
      detail(t.id);
    } catch (e) {
      message.textContent = e.message;
      message.className = "error";
      for (const f of (e.data && e.data.fields) || []) {
        const box = document.getElementById("error-" + f.field);
        if (box) box.textContent = f.message;
      }
      if (e.status === 401) askToken();
    }
  });

  function show(t, event) {
    let row = rows.get(t.id);
    if (!row) {
      row = el("tr", { "data-task-id": t.id });
      rows.set(t.id, row);
      tbody.prepend(row);
    }
    const latest = event ? event.text : (row.dataset.latest || "");
    row.dataset.latest = latest;
    const cancellable = ["queued", "running", "aborted"].includes(t.state);
    row.replaceChildren(
      el("td", {}, "#" + t.id),
      el("td", { class: "priority" }, String(t.priority || 0)),
      el("td", {}, el("a", { href: "#", onclick: e => { e.preventDefault(); selected = t.id; detail(t.id); } }, t.call)),
      el("td", { class: "state state-" + t.state }, t.state),
      el("td", {}, t.robot || ""),
      el("td", { class: "expected muted" }, t.expectedStart ? "start " + time(t.expectedStart) + ", finish " + time(t.expectedFinish) : ""),
      el("td", { class: "latest muted" }, latest),
      el("td", {}, cancellable ? el("button", { class: "cancel", onclick: () => api("DELETE", "/api/tasks/" + t.id).then(show).catch(e => alert(e.message)) }, "Cancel") : ""));
  }

  async function detail(id) {
    const t = await api("GET", "/api/tasks/" + id);
    const box = document.getElementById("detail");
    box.hidden = false;
    document.getElementById("detail-title").textContent = "#" + t.id + " " + t.call + ": " + t.state + (t.reason ? " (" + t.reason + ")" : "");
    document.getElementById("detail-events").textContent = t.events.map(e => time(e.at) + "  " + (e.robot ? e.robot + "  " : "") + e.text).join("\n");
  }

  load();
})();
