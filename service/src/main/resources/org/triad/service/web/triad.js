// Shared by the staff and operator pages: the token, calls to the API, and the live event stream.
"use strict";
const Triad = (() => {
  // one token per page: opening the staff link does not turn an open operator page into a staff one
  const KEY = "triad-token-" + (location.pathname.startsWith("/operator") ? "operator" : "staff");
  const fromHash = new URLSearchParams(location.hash.slice(1)).get("token");
  if (fromHash) {
    localStorage.setItem(KEY, fromHash);
    history.replaceState(null, "", location.pathname);
  }
  const token = () => localStorage.getItem(KEY) || "";

  async function api(method, path, body) {
    const init = { method, headers: { "Authorization": "Bearer " + token() } };
    if (body !== undefined) {
      init.headers["Content-Type"] = "application/json";
      init.body = JSON.stringify(body);
    }
    const r = await fetch(path, init);
    const text = await r.text();
    const data = text ? JSON.parse(text) : null;
    if (!r.ok) {
      const e = new Error((data && data.message) || r.statusText);
      e.status = r.status;
      e.data = data;
      throw e;
    }
    return data;
  }

  function live(handlers) {
    const source = new EventSource("/api/events?token=" + encodeURIComponent(token()));
    for (const [type, fn] of Object.entries(handlers)) {
      source.addEventListener(type, ev => fn(JSON.parse(ev.data)));
    }
    return source;
  }

  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === "class") e.className = v;
      else if (k.startsWith("on")) e.addEventListener(k.slice(2), v);
      else if (v !== null && v !== undefined) e.setAttribute(k, v);
    }
    for (const c of children.flat()) {
      if (c !== null && c !== undefined) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
    }
    return e;
  }

  function tokenForm(container, onSet) {
    const input = el("input", { id: "token", type: "password", placeholder: "access token" });
    container.append(el("label", { for: "token" }, "Access token"), input,
      el("button", { id: "set-token", onclick: () => { localStorage.setItem(KEY, input.value.trim()); onSet(); } }, "Use token"));
  }

  function time(iso) {
    return iso ? new Date(iso).toLocaleTimeString() : "";
  }

  return { api, live, el, token, tokenForm, time };
})();
