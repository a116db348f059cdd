// What the page shows, as plain values on window.beft (for people at the
// console and for the browser test) and mirrored into elements with ids.
// Times in nanoseconds are decimal strings: they exceed a double's integers.

const FRAME_WINDOW = 60;  // frames in the rolling mean of frameTimeMs
const RUN_STATES = ["waiting", "running", "finished", "failed"];
const RUN_MODES = ["run", "pause", "step"];

export function createPageState() {
  return {
    connected: false,
    serverName: "",
    mode: "live",            // "live" or "log"
    topics: [],              // advertised topics
    messages: {},            // topic -> messages received
    tick: -1,                // of the last ROBOT_STATE
    sceneTick: -1,           // GT_VERSION's scene_tick
    runState: "",            // RUN_STATUS
    runMessage: "",
    runMode: "",             // RUN_CONTROL_STATE: run, pause, step
    controlTick: -1,
    robot: null,             // {x, y, yaw, headYaw, tick, utime}
    objectCount: 0,          // objects in the last GT_OBJECTS
    drawnObjectCount: 0,     // of them, boxes and cylinders drawn
    scenario: "",
    hypothesisCount: 0,
    audioCount: 0,
    waypointCount: 0,
    taskCount: 0,
    logLines: 0,
    cadence: null,           // {panelMs, sceneMs, wholeStateMs}: how often the page draws the run's changes
    firingLines: 0,          // /firings lines received (the newest of each throttle interval)
    lastFiring: "",          // the newest of them
    markingStep: -1,
    netDrawn: false,         // the run's net drawn (metadata "net")
    netLit: [],              // experts whose transitions are lit now
    netLitSeen: [],          // every expert lit on the drawing so far
    netMarked: [],           // places holding tokens now, on the drawing
    colourFrames: 0,
    depthFrames: 0,
    panelsChanged: true,     // something the panels show changed since they were drawn
    frameTimeMs: 0,          // rolling mean of the intervals between the frames drawn
    frames: 0,               // animation frames drawn (asked for when something changed)
    renders: 0,              // of them, those that drew the 3-D view
    webGlInSoftware: false,  // WebGL drawn on the CPU: fewer, cheaper 3-D frames
    logTimeNs: "0",          // the server's time (Time frames), or the last receive time
    logStartNs: "0",
    logEndNs: "0",
  };
}

export function runStateName(state) {
  return RUN_STATES[state] ?? String(state);
}

export function runModeName(mode) {
  return RUN_MODES[mode] ?? String(mode);
}

// Rolling mean of the intervals between the frames drawn.
export class FrameClock {
  constructor(state) {
    this.state = state;
    this.intervals = [];
    this.sum = 0;
    this.last = 0;
  }

  tick(now) {
    if (this.last) {
      const interval = now - this.last;
      this.intervals.push(interval);
      this.sum += interval;
      if (this.intervals.length > FRAME_WINDOW) this.sum -= this.intervals.shift();
      this.state.frameTimeMs = this.sum / this.intervals.length;
    }
    this.last = now;
    this.state.frames++;
  }
}

function formatNs(ns) {
  const seconds = Number(BigInt(ns) / 1000000n) / 1000;
  return seconds > 1e6 ? new Date(seconds * 1000).toISOString().slice(11, 23) : `${seconds.toFixed(3)} s`;
}

// Writes the state's key values into the page's status elements.
export function mirrorIntoDom(state) {
  const put = (id, text) => {
    const node = document.getElementById(id);
    if (node && node.textContent !== text) node.textContent = text;
  };
  const robot = state.robot;
  put("connected", state.connected ? `connected${state.serverName ? ` to ${state.serverName}` : ""}` : "disconnected");
  put("mode", state.mode);
  put("tick", String(state.tick));
  put("run-state", state.runState + (state.runMessage ? `: ${state.runMessage}` : ""));
  const runState = document.getElementById("run-state");
  if (runState && runState.title !== runState.textContent) runState.title = runState.textContent;
  put("run-mode", state.runMode);
  put("robot-pose", robot ? `(${robot.x.toFixed(2)}, ${robot.y.toFixed(2)}) ${robot.yaw.toFixed(1)}°` : "–");
  put("object-count", String(state.objectCount));
  put("hypothesis-count", String(state.hypothesisCount));
  put("frame-time", `${state.frameTimeMs.toFixed(1)} ms`);
  put("log-time", state.logTimeNs === "0" ? "–" : formatNs(state.logTimeNs));
  document.body.dataset.mode = state.mode;
  document.body.dataset.connected = String(state.connected);
}
