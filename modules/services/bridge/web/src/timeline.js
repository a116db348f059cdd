// Where the page is in time: live, or in a log (the server has the "time"
// capability or its metadata says mode "log"), and the log's span for the
// seek slider: the server's metadata (start_ns, end_ns: beft-bridge's) when
// it gives them, else the span of the times seen so far.

const START_KEYS = ["start_ns", "start_time_ns"];
const END_KEYS = ["end_ns", "end_time_ns"];

function firstOf(metadata, keys) {
  for (const key of keys) {
    if (metadata[key] === undefined) continue;
    try {
      return BigInt(metadata[key]);
    } catch {
      return null;
    }
  }
  return null;
}

export class Timeline {
  constructor(state, slider) {
    this.state = state;
    this.slider = slider;
    this.start = null;
    this.end = null;
    this.fixedSpan = false;
    this.hasTimeFrames = false;
    this.dragging = false;
    if (slider) {
      slider.addEventListener("pointerdown", () => (this.dragging = true));
      slider.addEventListener("change", () => (this.dragging = false));
    }
  }

  serverInfo(info) {
    const metadata = info.metadata || {};
    const capabilities = info.capabilities || [];
    this.state.serverName = info.name || "";
    this.state.mode = capabilities.includes("time") || metadata.mode === "log" ? "log" : "live";
    const start = firstOf(metadata, START_KEYS);
    const end = firstOf(metadata, END_KEYS);
    if (start !== null && end !== null && end > start) {
      this.start = start;
      this.end = end;
      this.fixedSpan = true;
    }
    this.publishSpan();
  }

  time(ns) {
    this.hasTimeFrames = true;
    this.at(ns);
  }

  received(ns) {
    if (!this.hasTimeFrames) this.at(ns);
  }

  at(ns) {
    this.state.logTimeNs = ns.toString();
    if (!this.fixedSpan) {
      if (this.start === null || ns < this.start) this.start = ns;
      if (this.end === null || ns > this.end) this.end = ns;
      this.publishSpan();
    }
  }

  publishSpan() {
    this.state.logStartNs = (this.start ?? 0n).toString();
    this.state.logEndNs = (this.end ?? 0n).toString();
  }

  rangeNs() {
    return [this.start ?? 0n, this.end ?? 0n];
  }

  // The slider follows the time unless someone holds it.
  draw() {
    if (!this.slider || this.dragging || this.start === null || this.end <= this.start) return;
    const now = BigInt(this.state.logTimeNs);
    const position = Number(((now - this.start) * 1000n) / (this.end - this.start));
    const value = String(Math.max(0, Math.min(1000, position)));
    if (this.slider.value !== value) this.slider.value = value;
  }
}
