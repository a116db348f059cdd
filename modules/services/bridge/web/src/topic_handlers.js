// What the page does with each topic it subscribes: BEFT's channels (fields
// as in lcmtypes/*.lcm) and the bridge's camera and log topics (Foxglove's
// schemas). Each handler updates the page state and the parts that draw it.
import { runModeName, runStateName } from "./page_state.js";

export function topicHandlers(state, parts) {
  const handlers = new Map();
  const on = (topic, handle) => handlers.set(topic, handle);

  on("GT_OBJECTS", (m) => {
    parts.view.setWorldSize(m.world_width, m.world_height);
    parts.objects.update(m.objects || []);
    state.objectCount = (m.objects || []).length;
    state.drawnObjectCount = parts.objects.drawnCount;
    state.scenario = m.scenario || "";
  });
  on("GT_VERSION", (m) => (state.sceneTick = m.scene_tick));
  on("ROBOT_STATE", (m) => {
    parts.robot.update(m);
    state.tick = m.tick;
    state.robot = { x: m.x, y: m.y, yaw: m.yaw, headYaw: m.head_yaw, tick: m.tick, utime: m.utime };
  });
  const showHypotheses = () => {
    parts.hypotheses.update(parts.hypothesisList.current);
    state.hypothesisCount = parts.hypothesisList.current.length;
  };
  on("HYPOTHESES", (m) => {
    parts.hypothesisList.setKeyframe(m);
    showHypotheses();
  });
  on("HYPOTHESIS_CHANGES", (m) => {
    if (parts.hypothesisList.applyChanges(m)) showHypotheses();
  });
  on("AUDIO", (m) => {
    parts.audio.update(m.percepts || [], (id) => parts.objects.byId.get(id));
    state.audioCount = (m.percepts || []).length;
  });
  on("DYNAMIC_WEIGHTS", (m) => parts.weights.add(m));
  on("TASK_STACK", (m) => {
    parts.tasks.set(m);
    state.taskCount = (m.tasks || []).length;
  });
  on("PLAN_RESULT", (m) => {
    parts.path.update(m);
    state.waypointCount = parts.path.waypointCount;
  });
  on("OBSTACLE_MAP", (m) => parts.map.keyframe(m));
  on("OBSTACLE_MAP_CHANGES", (m) => parts.map.changes(m));
  on("MARKING", (m) => {
    parts.net.show(m);
    parts.marking.set(m);
    state.markingStep = m.step;
  });
  on("RUN_STATUS", (m) => {
    state.runState = runStateName(m.state);
    state.runMessage = m.message || "";
  });
  on("RUN_CONTROL_STATE", (m) => {
    state.runMode = runModeName(m.mode);
    state.controlTick = m.tick;
  });
  on("/camera/color", (m) => {
    parts.colour.show(m);
    state.colourFrames = parts.colour.frames;
  });
  on("/camera/depth", (m) => {
    parts.depth.show(m);
    state.depthFrames = parts.depth.frames;
  });
  on("/firings", (m) => {
    parts.lastFiring.set(m);
    state.firingLines++;
    state.lastFiring = m.message || "";
  });
  on("/log", (m) => {
    parts.log.add(m);
    state.logLines = parts.log.count;
  });
  return handlers;
}
