// The dynamic weights over time (DYNAMIC_WEIGHTS), like the paper's Fig. 4:
// one line per acoustic object, weight 0..1 against the tick, dashed lines
// at the three congruency states (0.25, 0.5, 0.75), and a title with the
// current task and the viewing direction.

import { context2d } from "./canvas_2d.js";

const PALETTE = ["#e6194b", "#3cb44b", "#4363d8", "#f58231", "#911eb4", "#42d4f4", "#f032e6", "#bfef45",
  "#fabed4", "#469990", "#dcbeff", "#9a6324", "#fffac8", "#800000", "#aaffc3", "#808000"];
const WINDOW_TICKS = 600;  // the last minute at dt = 0.1 s
const MAX_LINES = 16;      // the legend stays legible; the rest are drawn thin and grey

export class WeightsPlot {
  constructor(canvas, title) {
    this.canvas = canvas;
    this.title = title;
    this.series = new Map();  // object id -> [{tick, weight}]
    this.lastTick = -1;
    this.dirty = true;
  }

  add(message) {
    // A log sought backwards starts the plot again.
    if (message.tick < this.lastTick) this.series.clear();
    this.lastTick = message.tick;
    for (const w of message.weights || []) {
      if (!this.series.has(w.object_id)) this.series.set(w.object_id, []);
      const points = this.series.get(w.object_id);
      points.push({ tick: message.tick, weight: w.weight });
      while (points.length && points[0].tick < message.tick - WINDOW_TICKS) points.shift();
    }
    const direction = Number.isFinite(message.viewing_direction) ? `${message.viewing_direction.toFixed(0)}°` : "none";
    // Put on the page by draw(): a change to the page's text for every
    // message would have the browser lay out, paint and composite the page
    // at every display frame while a run goes at full speed.
    this.titleText = `task: ${message.current_task || "none"}, viewing direction: ${direction}`;
    this.dirty = true;
  }

  // Drawn from the animation frame, at most once per change.
  draw() {
    if (!this.dirty) return;
    this.dirty = false;
    if (this.titleText !== undefined && this.title.textContent !== this.titleText) this.title.textContent = this.titleText;
    const canvas = this.canvas;
    const width = canvas.clientWidth || 300;
    const height = canvas.clientHeight || 150;
    // A new size reallocates the canvas: set only when the layout changed it.
    if (canvas.width !== width) canvas.width = width;
    if (canvas.height !== height) canvas.height = height;
    const g = context2d(canvas);
    const pad = { left: 30, right: 90, top: 6, bottom: 16 };
    const plotW = width - pad.left - pad.right;
    const plotH = height - pad.top - pad.bottom;
    const last = Math.max(this.lastTick, 1);
    const first = Math.max(0, last - WINDOW_TICKS);
    const x = (tick) => pad.left + ((tick - first) / Math.max(1, last - first)) * plotW;
    const y = (weight) => pad.top + (1 - weight) * plotH;
    this.drawAxes(g, pad, plotW, plotH, first, last, y);
    let index = 0;
    for (const [id, points] of this.series) {
      const colour = index < MAX_LINES ? PALETTE[index % PALETTE.length] : "#777";
      g.strokeStyle = colour;
      g.lineWidth = index < MAX_LINES ? 1.6 : 0.6;
      g.beginPath();
      points.forEach((p, i) => (i ? g.lineTo(x(p.tick), y(p.weight)) : g.moveTo(x(p.tick), y(p.weight))));
      g.stroke();
      if (index < MAX_LINES) {
        g.fillStyle = colour;
        g.fillText(id.slice(0, 14), pad.left + plotW + 6, pad.top + 10 + index * 11);
      }
      index++;
    }
  }

  drawAxes(g, pad, plotW, plotH, first, last, y) {
    g.clearRect(0, 0, this.canvas.width, this.canvas.height);
    g.font = "10px sans-serif";
    g.strokeStyle = "#888";
    g.lineWidth = 1;
    g.strokeRect(pad.left, pad.top, plotW, plotH);
    g.setLineDash([4, 3]);
    for (const c of [0.25, 0.5, 0.75]) {
      g.beginPath();
      g.moveTo(pad.left, y(c));
      g.lineTo(pad.left + plotW, y(c));
      g.stroke();
    }
    g.setLineDash([]);
    g.fillStyle = "#aaa";
    for (const w of [0, 0.5, 1]) g.fillText(w.toFixed(1), 4, y(w) + 3);
    g.fillText(`tick ${first}`, pad.left, pad.top + plotH + 12);
    g.fillText(`${last}`, pad.left + plotW - 24, pad.top + plotH + 12);
  }
}
