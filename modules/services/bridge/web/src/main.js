// BEFT's viewer: connects to the bridge that served this page (Foxglove
// WebSocket protocol, JSON messages on BEFT's channel names), draws the run
// and sends the viewer's requests back.
import { FoxgloveClient } from "./foxglove_client.js";
import { SceneView } from "./scene_view.js";
import { ObjectLayer } from "./object_layer.js";
import { RobotModel } from "./robot_model.js";
import { PathLayer } from "./path_layer.js";
import { MapLayer } from "./map_layer.js";
import { HypothesisLayer, HypothesisList, HYPOTHESIS_STATES } from "./hypothesis_layer.js";
import { AudioLayer } from "./audio_layer.js";
import { WeightsPlot } from "./weights_plot.js";
import { CameraView } from "./camera_view.js";
import { LatestMessagePanel, LogList, showMarking, showTaskStack } from "./panels.js";
import { NetDrawing } from "./net_drawing.js";
import { Controls, wireButtons } from "./controls.js";
import { Pointer } from "./pointer.js";
import { createPageState, FrameClock, mirrorIntoDom } from "./page_state.js";
import { topicHandlers } from "./topic_handlers.js";
import { Timeline } from "./timeline.js";
import { FrameScheduler } from "./frame_scheduler.js";

const byId = (id) => document.getElementById(id);

// Camera images are the bulk of a run's traffic (a raw frame is a megabyte
// of base64): only the newest of each is decoded, on the panels' cadence,
// so that a page on a slow machine keeps up with the rest; and the bridge
// is asked for no more than that (throttleMs: the panels' cadence), so that
// the frames the page would drop are neither converted, sent nor received.
const LATEST_ONLY = new Set(["/camera/color", "/camera/depth"]);

// The arbiter's line per firing (ten a tick at full speed): the newest is
// shown under the net, on the panels' cadence; every other line of the
// processes' log comes on /log.
const FIRINGS = "/firings";

// Topics whose every message holds the whole of what it shows (changes are
// relative to the last keyframe): the bridge need send only the newest as
// often as the page draws it (a run at full speed sends the marking ten
// times a tick), which is the throttle asked for them: the shorter of the
// 3-D view's and the panels' cadence. The keyframes, the weights (a plot
// over time) and the log lines come whole.
const WHOLE_STATE = new Set(["ROBOT_STATE", "GT_VERSION", "MARKING", "TASK_STACK", "AUDIO", "PLAN_RESULT",
  "HYPOTHESIS_CHANGES", "OBSTACLE_MAP_CHANGES", "RUN_STATUS", "RUN_CONTROL_STATE"]);

// The text panels, the weights plot, the camera images and the status line
// are drawn at most this often [ms]: each drawing lays out and paints the page, which at a
// run's full speed (a hundred messages a second) would take a core.
const PANEL_MS = 250;
// When the browser draws in software (scene_view.js), every drawing is
// composited on the CPU, beside the run: once a second, in the same frame
// as the 3-D view (scene_view.js), so that the page is composited once.
const SOFTWARE_PANEL_MS = 1000;

// Hands `text` to the topic's handler; a malformed message costs itself only.
function handleText(handle, topic, text) {
  try {
    handle(JSON.parse(text));
  } catch (error) {
    console.warn(`${topic}: ${error}`);
  }
}

// The newest message of each LATEST_ONLY topic, handled by drain(now).
class LatestOnly {
  constructor(intervalMs) {
    this.intervalMs = intervalMs;
    this.pending = new Map();
    this.lastDrainMs = -Infinity;
  }
  keep(topic, handle, text) {
    this.pending.set(topic, { handle, text });
  }
  drain(nowMs) {
    if (this.pending.size === 0 || nowMs - this.lastDrainMs < this.intervalMs) return false;
    this.lastDrainMs = nowMs;
    for (const [topic, { handle, text }] of this.pending) handleText(handle, topic, text);
    this.pending.clear();
    return true;
  }
}

function createParts(state) {
  const view = new SceneView(byId("scene"));
  const net = new NetDrawing(byId("net"), state);
  return {
    net,
    view,
    objects: new ObjectLayer(view),
    robot: new RobotModel(view),
    path: new PathLayer(view),
    map: new MapLayer(view),
    hypotheses: new HypothesisLayer(view),
    hypothesisList: new HypothesisList(),
    audio: new AudioLayer(view),
    weights: new WeightsPlot(byId("weights"), byId("weights-title")),
    colour: new CameraView(byId("camera-colour"), byId("camera-colour-caption")),
    depth: new CameraView(byId("camera-depth"), byId("camera-depth-caption")),
    log: new LogList(byId("log")),
    tasks: new LatestMessagePanel((message) => showTaskStack(byId("tasks"), message)),
    // On the drawn net when there is one; the marking is listed as well.
    marking: new LatestMessagePanel((message) => showMarking(byId("marking"), message)),
    lastFiring: new LatestMessagePanel((message) => (byId("last-firing").textContent = message.message || "")),
  };
}

function showLegend() {
  const legend = byId("legend");
  for (const state of HYPOTHESIS_STATES) {
    const item = document.createElement("span");
    item.className = "legend-item";
    item.style.setProperty("--swatch", `#${state.colour.toString(16).padStart(6, "0")}`);
    item.textContent = state.name;
    legend.append(item);
  }
}

function start() {
  const state = createPageState();
  const parts = createParts(state);
  state.webGlInSoftware = parts.view.software;
  const timeline = new Timeline(state, byId("seek"));
  const handlers = topicHandlers(state, parts);
  const panelMs = state.webGlInSoftware ? SOFTWARE_PANEL_MS : PANEL_MS;
  // How often it draws what the run changes, and so how often it asks for the whole-state topics [ms].
  state.cadence = { panelMs, sceneMs: parts.view.dataFrameMs, wholeStateMs: Math.min(panelMs, parts.view.dataFrameMs) };
  const latest = new LatestOnly(panelMs);
  const scheduler = new FrameScheduler(() => false);
  // What the run or the server changed: drawn at the next poll.
  const changed = () => {
    state.panelsChanged = true;
    scheduler.wake();
  };
  // What a person does with the view: drawn on the next animation frame.
  parts.view.onInteraction = () => scheduler.wakeNow();
  // A viewer on another host sends controls with the bridge's token, given
  // to the page as ?token=... and passed on to the WebSocket.
  const token = new URLSearchParams(location.search).get("token");
  const query = token ? `?token=${encodeURIComponent(token)}` : "";
  const wsUrl = `${location.protocol === "https:" ? "wss" : "ws"}://${location.host}/${query}`;
  const client = new FoxgloveClient(wsUrl, {
    onOpen: () => ((state.connected = true), changed()),
    onClose: () => ((state.connected = false), changed()),
    onServerInfo: (info) => {
      changed();
      timeline.serverInfo(info);
      const drawing = (info.metadata || {}).net;
      if (drawing && !state.netDrawn) parts.net.load(drawing).catch((error) => console.warn(`net: ${error}`));
    },
    onAdvertise: () => ((state.topics = [...client.channelsById.values()].map((c) => c.topic)), changed()),
    onMessage: (topic, text, receiveNs) => {
      const handle = handlers.get(topic) || handlers.get(topic.replace(/^\//, ""));
      if (!handle) return;
      state.messages[topic] = (state.messages[topic] || 0) + 1;
      timeline.received(receiveNs);
      changed();
      if (LATEST_ONLY.has(topic)) return latest.keep(topic, handle, text);
      handleText(handle, topic, text);
      parts.view.invalidate(true);
    },
    onTime: (ns) => (timeline.time(ns), changed()),
  });
  const withSlash = (topics) => topics.flatMap((topic) => [topic, `/${topic}`]);
  const throttled = (topic) =>
    WHOLE_STATE.has(topic) || LATEST_ONLY.has(topic) || LATEST_ONLY.has(`/${topic}`) || topic === FIRINGS;
  client.want(withSlash([...handlers.keys()].filter((topic) => !throttled(topic))));
  client.want(withSlash([...WHOLE_STATE]), state.cadence.wholeStateMs);
  client.want(withSlash([...LATEST_ONLY].map((topic) => topic.replace(/^\//, ""))), panelMs);
  client.want([FIRINGS], panelMs);
  const controls = new Controls(client);
  wireButtons(controls, timeline);
  const pointer = new Pointer(parts.view, parts, controls, byId("tooltip"));
  showLegend();
  window.beft = Object.assign(state, {
    actions: controls,
    sent: controls.sent,
    screenOf: (x, y, z) => parts.view.screenOf(x, y, z),
  });
  Object.assign(scheduler, pageDrawer(state, parts, pointer, timeline, latest, panelMs));
  scheduler.wakeNow();
}

// Draws what changed: the 3-D view when due (scene_view.js), the panels at
// most every panelMs; draw returns true when something is left to draw
// later, nextDueMs when the first of it is due (frame_scheduler.js).
function pageDrawer(state, parts, pointer, timeline, latest, panelMs) {
  const clock = new FrameClock(state);
  let lastPanelMs = -Infinity;
  const nextDueMs = () =>
    Math.min(
      latest.pending.size > 0 ? latest.lastDrainMs + latest.intervalMs : Infinity,
      parts.view.dataChanged ? parts.view.lastRenderMs + parts.view.dataFrameMs : Infinity,
      state.panelsChanged ? lastPanelMs + panelMs : Infinity,
    );
  const draw = (now) => {
    clock.tick(now);
    latest.drain(now);
    pointer.update();
    if (parts.view.render(now)) state.renders++;
    if (now - lastPanelMs >= panelMs && state.panelsChanged) {
      lastPanelMs = now;
      state.panelsChanged = false;
      drawPanels(state, parts, timeline);
    }
    return state.panelsChanged || parts.view.dataChanged || latest.pending.size > 0;
  };
  return { draw, nextDueMs };
}

function drawPanels(state, parts, timeline) {
  parts.weights.draw();
  parts.tasks.draw();
  parts.marking.draw();
  parts.lastFiring.draw();
  parts.net.draw();
  parts.log.draw();
  timeline.draw();
  mirrorIntoDom(state);
}

start();
