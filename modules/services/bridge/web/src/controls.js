// What the page sends: run control on a live run, tasks, and playback of a
// log, each as JSON on a client channel of the bridge.
export const TOPIC_RUN_CONTROL = "/beft/run_control";
export const TOPIC_TASK = "/beft/task";
export const TOPIC_PLAYBACK = "/beft/playback";

export class Controls {
  constructor(client) {
    this.client = client;
    this.speed = 1;
    this.playing = false;
    this.sent = [];  // the last few requests, for the page's state and tests
  }

  send(topic, message) {
    const ok = this.client.publish(topic, message);
    this.sent.push({ topic, message: typeof message === "string" ? JSON.parse(message) : message, ok });
    if (this.sent.length > 20) this.sent.shift();
    return ok;
  }

  pause() { return this.send(TOPIC_RUN_CONTROL, { action: "pause" }); }
  step() { return this.send(TOPIC_RUN_CONTROL, { action: "step" }); }
  run() { return this.send(TOPIC_RUN_CONTROL, { action: "run" }); }
  goto(x, y) { return this.send(TOPIC_TASK, { action: "goto", x, y }); }
  lookAt(objectId) { return this.send(TOPIC_TASK, { action: "look_at", object_id: objectId }); }
  clear() { return this.send(TOPIC_TASK, { action: "clear" }); }

  // Playback of a log. time_ns is a uint64 beyond a double's exact integers:
  // it is written into the JSON text from a BigInt, digit for digit.
  playback(action, timeNs) {
    const time = timeNs === undefined ? "" : `,"time_ns":${BigInt(timeNs).toString()}`;
    const speed = action === "play" ? `,"speed":${Number(this.speed)}` : "";
    return this.send(TOPIC_PLAYBACK, `{"action":"${action}"${time}${speed}}`);
  }
  play() {
    this.playing = true;
    return this.playback("play");
  }
  playbackPause() {
    this.playing = false;
    return this.playback("pause");
  }
  playbackStep() {
    this.playing = false;  // a step ends paused
    return this.playback("step");
  }
  seek(timeNs) { return this.playback("seek", timeNs); }
  // A new speed applies at once while playing, else from the next play.
  setSpeed(speed) {
    this.speed = speed;
    return this.playing ? this.playback("play") : true;
  }
}

function on(id, event, handler) {
  const node = document.getElementById(id);
  if (node) node.addEventListener(event, handler);
  return node;
}

// Wires the buttons of index.html; timeline: {rangeNs() -> [start, end] BigInts}.
export function wireButtons(controls, timeline) {
  on("pause", "click", () => controls.pause());
  on("step", "click", () => controls.step());
  on("run", "click", () => controls.run());
  on("clear-stack", "click", () => controls.clear());
  on("play", "click", () => controls.play());
  on("playback-pause", "click", () => controls.playbackPause());
  on("playback-step", "click", () => controls.playbackStep());
  on("speed", "change", (event) => controls.setSpeed(Number(event.target.value) || 1));
  // The slider runs over 0..1000 of the log's span.
  on("seek", "change", (event) => {
    const [start, end] = timeline.rangeNs();
    if (end <= start) return;
    const at = start + ((end - start) * BigInt(Math.round(Number(event.target.value)))) / 1000n;
    controls.seek(at);
  });
}
