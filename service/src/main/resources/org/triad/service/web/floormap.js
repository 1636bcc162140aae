// Draws a robot's floor map (metres, y up) as the simulation's pictures do: rooms, walls, doors
// (red when closed), waypoints, items, people and robots.
"use strict";
const FloorMap = (() => {
  function draw(canvas, m) {
    const ratio = window.devicePixelRatio || 1;
    const w = canvas.clientWidth, h = canvas.clientHeight;
    if (canvas.width !== w * ratio) { canvas.width = w * ratio; canvas.height = h * ratio; }
    const g = canvas.getContext("2d");
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.clearRect(0, 0, w, h);
    const b = m.bounds, pad = 8;
    const s = Math.min((w - 2 * pad) / (b.maxX - b.minX), (h - 2 * pad) / (b.maxY - b.minY));
    const X = x => pad + (x - b.minX) * s, Y = y => h - pad - (y - b.minY) * s;
    g.font = "10px system-ui, sans-serif";
    for (const a of m.areas) {
      g.fillStyle = a.corridor ? "#eef0f3" : "#fbfbf7";
      g.fillRect(X(a.box.minX), Y(a.box.maxY), (a.box.maxX - a.box.minX) * s, (a.box.maxY - a.box.minY) * s);
      if (!a.corridor) { g.fillStyle = "#999"; g.fillText(a.name, X(a.box.minX) + 3, Y(a.box.maxY) + 11); }
    }
    g.strokeStyle = "#333"; g.lineWidth = 2;
    for (const l of m.walls) line(g, X(l.x1), Y(l.y1), X(l.x2), Y(l.y2));
    g.lineWidth = 3;
    for (const d of m.doors) {
      g.strokeStyle = d.open ? "#7cc47f" : "#d62728";
      line(g, X(d.leaf.x1), Y(d.leaf.y1), X(d.leaf.x2), Y(d.leaf.y2));
    }
    g.fillStyle = "#bbb";
    for (const p of m.waypoints) dot(g, X(p.x), Y(p.y), 2);
    g.fillStyle = "#e08a00";
    for (const i of m.items) { g.fillRect(X(i.x) - 3, Y(i.y) - 3, 6, 6); g.fillText(i.name, X(i.x) + 5, Y(i.y) + 3); }
    g.fillStyle = "#f0a030";
    for (const p of m.people) { dot(g, X(p.x), Y(p.y), 5); g.fillText(p.name, X(p.x) + 7, Y(p.y) - 5); }
    for (const r of m.robots) {
      g.fillStyle = "#1c5fb8";
      dot(g, X(r.x), Y(r.y), 7);
      g.fillStyle = "#123";
      g.fillText(r.name + (r.note ? " [" + r.note + "]" : ""), X(r.x) + 9, Y(r.y) + 4);
    }
    g.fillStyle = "#777";
    g.fillText("t = " + m.time.toFixed(1) + " s", w - 70, h - 4);
  }

  function line(g, x1, y1, x2, y2) { g.beginPath(); g.moveTo(x1, y1); g.lineTo(x2, y2); g.stroke(); }
  function dot(g, x, y, r) { g.beginPath(); g.arc(x, y, r, 0, 2 * Math.PI); g.fill(); }

  return { draw };
})();
