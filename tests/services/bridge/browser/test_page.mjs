// The viewer page against a scripted Foxglove server (fake_bridge.mjs): what
// it draws from BEFT's JSON messages and what it sends back, in headless
// Chromium. Needs no run and no beft-bridge.
//   node test_page.mjs --web BUILD/share/beft/web --out DIR
import assert from "node:assert/strict";
import { existsSync } from "node:fs";
import { join } from "node:path";
import { FakeBridge } from "./fake_bridge.mjs";
import { Checks, freePort, launchBrowser, openPage, option, pageState, screenshot, skip, sleep, waitForState } from "./browser.mjs";

const webDir = option("--web");
const outDir = option("--out", "viewer-page-test");
if (!webDir || !existsSync(join(webDir, "app.js"))) skip(`the built page is missing (${webDir}/app.js): build target beft_web`);

const TOPICS = ["GT_OBJECTS", "GT_VERSION", "ROBOT_STATE", "HYPOTHESES", "HYPOTHESIS_CHANGES", "AUDIO", "DYNAMIC_WEIGHTS",
  "TASK_STACK", "PLAN_RESULT", "OBSTACLE_MAP", "OBSTACLE_MAP_CHANGES", "MARKING", "RUN_STATUS", "RUN_CONTROL_STATE",
  "/camera/color", "/camera/depth", "/log", "/firings"];
const WORLD = { width: 160, height: 120 };
const BLOCK = { id: "center_block", x: 80, y: 60 };
const LOG_START = 1764230000123456789n;  // beyond a double's exact integers
const LOG_END = LOG_START + 120n * 1000000000n;

// A district of `count` objects north of the centre (none between the
// camera and the centre block), half boxes, half cylinders.
function district(count) {
  const objects = [{ id: BLOCK.id, label: "wall", activity: "", x: BLOCK.x, y: BLOCK.y, z: 0, yaw: 30, shape: 1,
    size_x: 4, size_y: 4, size_z: 3, radius: 0, color_rgb: 0xc04040 }];
  for (let i = 1; i < count; i++) {
    const cylinder = i % 2 === 0;
    objects.push({ id: `thing_${i}`, label: cylinder ? "person" : "car", activity: "idle", x: 5 + (i % 30) * 5,
      y: 75 + Math.floor(i / 30) * 3, z: 0, yaw: i * 7, shape: cylinder ? 2 : 1, size_x: 1.5, size_y: 0.8,
      size_z: cylinder ? 1.8 : 1.4, radius: cylinder ? 0.3 : 0, color_rgb: (i * 2654435761) & 0xffffff });
  }
  return { tick: 0, world_width: WORLD.width, world_height: WORLD.height, scenario: "page_test", objects };
}

function hypothesis(id, x, y, extra = {}) {
  return { object_id: id, x, y, z: 0, best_category: "person", confidence: 0.8, seen: true, heard: false, seen_as: "person",
    heard_as: "", verified: false, falsified: false, ...extra };
}

const robot = (tick) => ({ tick, utime: tick * 100000, x: 10 + 0.1 * tick, y: 20, yaw: 45, head_yaw: 10, head_pitch: 0,
  radius: 0.35, camera_height: 1.5, collided: false });

function sendScene(bridge) {
  bridge.publish("GT_OBJECTS", district(450));
  bridge.publish("ROBOT_STATE", robot(42));
  bridge.publish("HYPOTHESES", { tick: 40, hypotheses: [hypothesis("a", 30, 30), hypothesis("b", 40, 30), hypothesis("c", 50, 30)] });
  bridge.publish("HYPOTHESIS_CHANGES", { tick: 42, keyframe_tick: 40, num_hypotheses: 4,
    changed: [hypothesis("b", 40, 30, { verified: true, heard: true }), hypothesis("d", 60, 30, { seen: false, heard: true })] });
  bridge.publish("OBSTACLE_MAP", { tick: 40, width: 4, height: 2, resolution: 40, origin_x: 0, origin_y: 0, encoding: 1,
    data: Buffer.from([3, 1, 1, 2, 4, 0]).toString("base64") });
  bridge.publish("PLAN_RESULT", { success: true, waypoints: [{ x: 10, y: 20, yaw: 0 }, { x: 20, y: 25, yaw: 30 }, { x: 30, y: 30, yaw: 60 }] });
  bridge.publish("AUDIO", { tick: 42, percepts: [{ object_id: "thing_2", est_x: 12, est_y: 70, est_z: 0, acoustic_label: "person", activity: "yelling" }] });
  bridge.publish("DYNAMIC_WEIGHTS", { tick: 42, viewing_direction: 90, current_task: "explore", weights: [{ object_id: "thing_2", weight: 0.75 }] });
  bridge.publish("TASK_STACK", { tick: 42, tasks: [{ kind: "goto", x: 5, y: 6, status: 1, priority: 1, origin: "user", object_id: "" }] });
  bridge.publish("MARKING", { tick: 42, step: 7, event: "fire world", place_ids: ["p_idle", "p_world"], tokens: [0, 1], running: ["world"] });
  bridge.publish("RUN_STATUS", { tick: 42, state: 1, message: "" });
  bridge.publish("RUN_CONTROL_STATE", { tick: 42, mode: 1, origin: "viewer" });
  bridge.publish("/camera/color", { width: 4, height: 2, encoding: "rgb8", step: 12, data: Buffer.alloc(24, 200).toString("base64") });
  bridge.publish("/log", { timestamp: { sec: 4, nsec: 200000000 }, level: 2, message: "vision: 3 obstacles", name: "vision" });
  bridge.publish("/firings", { timestamp: { sec: 4, nsec: 300000000 }, level: 2, name: "arbiter",
    message: "tick    42  firing    420  world            ok           1.200 ms" });
}

async function lastReceived(bridge, topic, count = 1) {
  for (let i = 0; i < 100 && bridge.received.filter((r) => r.topic === topic).length < count; i++) await sleep(50);
  const list = bridge.received.filter((r) => r.topic === topic);
  assert.ok(list.length >= count, `nothing (more) on ${topic}`);
  return list[list.length - 1];
}

async function livePage(checks, browser) {
  const bridge = new FakeBridge(webDir, TOPICS, { capabilities: ["clientPublish"] });
  const port = await freePort();
  await bridge.listen(port);
  const page = await openPage(browser, `http://127.0.0.1:${port}/`);
  await checks.run("connects and subscribes to every topic it draws", async () => {
    await waitForState(page, (s) => s.connected && s.topics.length > 0);
    for (let i = 0; i < 50 && !TOPICS.every((t) => bridge.subscribed(t)); i++) await sleep(100);
    assert.deepEqual(TOPICS.filter((t) => !bridge.subscribed(t)), []);
  });
  await checks.run("asks the bridge to throttle whole-state topics, cameras and firings only, never keyframes, weights or log lines", async () => {
    const { cadence, webGlInSoftware } = await pageState(page);
    // With a GPU the 3-D view follows the run ten times a second and the panels four; drawn in
    // software, both once a second, in one frame.
    assert.deepEqual(cadence, webGlInSoftware ? { panelMs: 1000, sceneMs: 1000, wholeStateMs: 1000 }
      : { panelMs: 250, sceneMs: 100, wholeStateMs: 100 });
    // The whole-state topics as often as the page draws them, no more.
    for (const topic of ["ROBOT_STATE", "MARKING", "TASK_STACK", "HYPOTHESIS_CHANGES", "OBSTACLE_MAP_CHANGES"])
      assert.equal(bridge.throttles.get(topic), cadence.wholeStateMs, topic);
    // The cameras and the newest firing at the panels' cadence.
    for (const topic of ["/camera/color", "/camera/depth", "/firings"]) assert.equal(bridge.throttles.get(topic), cadence.panelMs, topic);
    for (const topic of ["GT_OBJECTS", "HYPOTHESES", "OBSTACLE_MAP", "DYNAMIC_WEIGHTS", "/log"])
      assert.equal(bridge.throttles.get(topic), 0, topic);
  });
  sendScene(bridge);
  await checks.run("draws the 450 objects, the robot and the hypotheses", async () => {
    const state = await waitForState(page, (s) => s.objectCount === 450 && s.robot && s.hypothesisCount === 4);
    assert.equal(state.drawnObjectCount, 450);
    assert.equal(state.tick, 42);
    assert.ok(Math.abs(state.robot.x - 14.2) < 1e-9 && state.robot.y === 20 && state.robot.yaw === 45, JSON.stringify(state.robot));
    assert.equal(state.waypointCount, 3);
    assert.equal(state.audioCount, 1);
    assert.equal(state.taskCount, 1);
    assert.equal(state.markingStep, 7);
    assert.equal(state.runState, "running");
    assert.equal(state.runMode, "pause");
    assert.equal(state.logLines, 1);
    assert.equal(state.firingLines, 1);
    // The newest firing under the net, on the panels' cadence.
    await page.waitForFunction(() => document.getElementById("last-firing").textContent.includes("firing    420  world"),
      { timeout: 20000 });
    // The page mirrors its state into the DOM on its next animation frame.
    await page.waitForFunction(() => document.getElementById("tick").textContent === "42" &&
      document.getElementById("object-count").textContent === "450", { timeout: 20000 });
  });
  await checks.run("run control buttons send pause, step and run", async () => {
    for (const [button, action] of [["#pause", "pause"], ["#step", "step"], ["#run", "run"]]) {
      const before = bridge.received.filter((r) => r.topic === "/beft/run_control").length;
      await page.click(button);
      assert.deepEqual((await lastReceived(bridge, "/beft/run_control", before + 1)).message, { action });
    }
    await page.click("#clear-stack");
    assert.deepEqual((await lastReceived(bridge, "/beft/task")).message, { action: "clear" });
  });
  await checks.run("a click on the ground sends goto there, a shift-click on an object look_at", async () => {
    await waitForState(page, (s) => s.renders > 0);
    const ground = await page.evaluate(() => window.beft.screenOf(40, 20, 0));
    await page.mouse.click(ground.x, ground.y);
    const goto = (await lastReceived(bridge, "/beft/task", 2)).message;
    assert.equal(goto.action, "goto");
    assert.ok(Math.abs(goto.x - 40) < 0.5 && Math.abs(goto.y - 20) < 0.5, JSON.stringify(goto));
    const block = await page.evaluate((b) => window.beft.screenOf(b.x, b.y, 1.5), BLOCK);
    await page.keyboard.down("Shift");
    await page.mouse.click(block.x, block.y);
    await page.keyboard.up("Shift");
    assert.deepEqual((await lastReceived(bridge, "/beft/task", 3)).message, { action: "look_at", object_id: BLOCK.id });
  });
  await checks.run("a hypothesis shows its label on hover only", async () => {
    await page.mouse.move(5, 5);  // off the view: no label
    await page.waitForFunction(() => document.getElementById("tooltip").hidden, { timeout: 10000 });
    const marker = await page.evaluate(() => window.beft.screenOf(40, 30, 2.3));
    await page.mouse.move(marker.x, marker.y);
    await page.waitForFunction(() => !document.getElementById("tooltip").hidden, { timeout: 10000 });
    const text = await page.$eval("#tooltip", (e) => e.textContent);
    assert.match(text, /^b: person .*verified/);
  });
  await checks.run("a flood of log lines and task stacks is drawn in batches: the last 500 lines, the last stack", async () => {
    const before = await pageState(page);
    for (let i = 0; i < 1200; i++) {
      bridge.publish("/log", { timestamp: { sec: 5 + i, nsec: 0 }, level: 2, message: `line ${i}`, name: "flood" });
      bridge.publish("TASK_STACK", { tick: 43 + i, tasks: [{ kind: "goto", x: i, y: 6, status: 1, priority: 1, origin: "user", object_id: "" }] });
    }
    await waitForState(page, (s, expected) => s.logLines === expected, before.logLines + 1200);
    await page.waitForFunction(() => {
      const lines = document.querySelectorAll("#log li");
      return lines.length === 500 && lines[lines.length - 1].textContent.endsWith("line 1199") &&
        document.querySelector("#tasks li").textContent.includes("(1199.0, 6.0)");
    }, { timeout: 20000 });
    const first = await page.$eval("#log li", (e) => e.textContent);
    assert.ok(first.endsWith("line 700"), first);
  });
  await checks.run("WebGL drawn in software (SwiftShader here) is told and drawn without multisampling", async () => {
    const state = await pageState(page);
    assert.equal(state.webGlInSoftware, true);
    const antialias = await page.evaluate(() => document.querySelector("#scene canvas").getContext("webgl2").getContextAttributes().antialias);
    assert.equal(antialias, false);
  });
  await checks.run("the page runs without errors and counts its frames", async () => {
    const state = await waitForState(page, (s) => s.frameTimeMs > 0);
    console.log(`frame time with 450 objects: ${state.frameTimeMs.toFixed(1)} ms`);
    await screenshot(page, outDir, "page_live");
    assert.deepEqual(page.errors, []);
  });
  await page.close();
  await bridge.close();
}

async function logPage(checks, browser) {
  const metadata = { mode: "log", start_ns: LOG_START.toString(), end_ns: LOG_END.toString() };
  const bridge = new FakeBridge(webDir, TOPICS, { capabilities: ["clientPublish", "time"], metadata });
  const port = await freePort();
  await bridge.listen(port);
  const page = await openPage(browser, `http://127.0.0.1:${port}/`);
  await checks.run("a log shows its time and the playback controls", async () => {
    await waitForState(page, (s) => s.connected && s.mode === "log");
    for (let i = 0; i < 50 && !bridge.subscribed("ROBOT_STATE"); i++) await sleep(100);
    bridge.sendTime(LOG_START + 7n);
    const state = await waitForState(page, (s, t) => s.logTimeNs === t, (LOG_START + 7n).toString());
    assert.equal(state.logStartNs, LOG_START.toString());
    await page.waitForFunction(() => document.getElementById("play").offsetParent !== null &&
      document.getElementById("pause").offsetParent === null, { timeout: 20000 });
  });
  await checks.run("play, pause, step and seek go out on /beft/playback, time_ns to the nanosecond", async () => {
    await page.click("#play");
    assert.equal((await lastReceived(bridge, "/beft/playback", 1)).message.action, "play");
    await page.click("#playback-step");
    assert.equal((await lastReceived(bridge, "/beft/playback", 2)).message.action, "step");
    await page.$eval("#seek", (slider) => {
      slider.value = "500";
      slider.dispatchEvent(new Event("change"));
    });
    const seek = await lastReceived(bridge, "/beft/playback", 3);
    assert.equal(seek.message.action, "seek");
    assert.match(seek.text, new RegExp(`"time_ns":${(LOG_START + (LOG_END - LOG_START) / 2n).toString()}[,}]`));
    await page.select("#speed", "5");  // paused: taken at the next play
    await page.click("#play");
    assert.deepEqual((await lastReceived(bridge, "/beft/playback", 4)).message, { action: "play", speed: 5 });
    await page.select("#speed", "2");  // playing: at once
    assert.deepEqual((await lastReceived(bridge, "/beft/playback", 5)).message, { action: "play", speed: 2 });
  });
  await checks.run("a seek's messages move the robot back", async () => {
    bridge.publish("ROBOT_STATE", robot(90), LOG_START + 9000000000n);
    await waitForState(page, (s) => s.tick === 90);
    bridge.publish("ROBOT_STATE", robot(30), LOG_START + 3000000000n);
    const state = await waitForState(page, (s) => s.tick === 30);
    assert.ok(Math.abs(state.robot.x - 13) < 1e-9, JSON.stringify(state.robot));
    await screenshot(page, outDir, "page_log");
    assert.deepEqual(page.errors, []);
  });
  await page.close();
  await bridge.close();
}

const checks = new Checks();
const browser = await launchBrowser();
try {
  await livePage(checks, browser);
  await logPage(checks, browser);
} finally {
  await browser.close();
}
checks.finish();
