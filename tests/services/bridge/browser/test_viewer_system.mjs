// The viewer on a real run and a real log, in headless Chromium: the yard
// mission with its bridge (beft-run --view --port P), then a log of it
// played by beft-bridge --log. Everything is checked from the page's own
// state (window.beft), and each check leaves a screenshot.
//   node test_viewer_system.mjs --bin BUILD/bin --source REPO --out DIR [--part live|log]
import assert from "node:assert/strict";
import { existsSync, mkdirSync, readFileSync, rmSync } from "node:fs";
import { join } from "node:path";
import { Checks, freePort, launchBrowser, openPage, option, pageState, screenshot, skip, sleep, waitForState } from "./browser.mjs";
import { readLogEvents, robotStateAt, robotStates } from "./lcm_log.mjs";
import { runProgram, startProcess, stopProcess, waitForHttp } from "./processes.mjs";

const bin = option("--bin");
const source = option("--source");
const outDir = option("--out", "viewer-system-test");
const part = option("--part", "all");
const scenario = join(source, "scenarios", "yard.xml");
const STABLE_MS = 3000;  // how long a held tick must stay put to count as held
const LOG_TICKS = 80;
const defaultNet = join(source, "scenarios", "nets", "default.pnml");

function preconditions() {
  for (const program of ["beft-run", "beft-bridge"])
    if (!existsSync(join(bin, program))) skip(`${program} is not built (${join(bin, program)})`);
  const help = runProgram(join(bin, "beft-run"), ["--help"], { cwd: source, timeoutMs: 20000 }).output;
  if (!help.includes("--view")) skip("beft-run has no --view (the run's bridge) yet");
  if (!existsSync(join(bin, "..", "share", "beft", "web", "app.js"))) skip("the viewer page is not built (target beft_web)");
}

// The places of the run's net: every <place> element of the PNML file.
function netPlaceCount() {
  return (readFileSync(defaultNet, "utf8").replace(/<!--[\s\S]*?-->/g, "").match(/<place\b/g) || []).length;
}

// The scenario's objects: every <object> element of the file.
function scenarioObjectCount() {
  return (readFileSync(scenario, "utf8").replace(/<!--[\s\S]*?-->/g, "").match(/<object\b/g) || []).length;
}

// Waits until the page's tick has stayed the same for STABLE_MS; returns it.
async function heldTick(page) {
  for (let attempt = 0; attempt < 20; attempt++) {
    const before = (await pageState(page)).tick;
    await sleep(STABLE_MS);
    const after = await pageState(page);
    if (after.tick === before) return after.tick;
  }
  throw new Error("the tick never held still");
}

async function liveRun(checks, browser) {
  const port = await freePort();
  const run = startProcess(join(bin, "beft-run"), [scenario, "--view", "--port", String(port), "--out", join(outDir, "live_run")],
    { cwd: source, logFile: join(outDir, "live_run.out") });
  try {
    await waitForHttp(`http://127.0.0.1:${port}/`, run);
    const page = await openPage(browser, `http://127.0.0.1:${port}/`);
    await checks.run("live: the scene shows the scenario's objects and the robot", async () => {
      const state = await waitForState(page, (s, n) => s.connected && s.objectCount === n && s.robot !== null,
        scenarioObjectCount(), 120000);
      assert.equal(state.mode, "live");
      assert.ok(state.drawnObjectCount > 0);
      await screenshot(page, outDir, "live_scene");
    });
    await checks.run("live: the tick advances", async () => {
      const start = (await pageState(page)).tick;
      await waitForState(page, (s, t) => s.tick >= t + 5, start, 120000);
    });
    await checks.run("live: pause holds the tick, step advances it by exactly one", async () => {
      await page.click("#pause");
      await waitForState(page, (s) => s.runMode === "pause", null, 60000);
      const held = await heldTick(page);
      await page.click("#step");
      await waitForState(page, (s, t) => s.tick === t + 1, held, 60000);
      assert.equal(await heldTick(page), held + 1);
      await screenshot(page, outDir, "live_stepped");
    });
    await checks.run("live: run goes on", async () => {
      const held = (await pageState(page)).tick;
      await page.click("#run");
      await waitForState(page, (s, t) => s.tick >= t + 5, held, 120000);
      assert.deepEqual(page.errors, []);
      await screenshot(page, outDir, "live_running");
    });
    await checks.run("live: the run's net is drawn as `net draw` lays it out and lights the experts firing", async () => {
      // Each tick lights every expert of the schedule in turn; a frame shows only the newest marking.
      await waitForState(page, (s) => s.netDrawn && s.netLitSeen.length >= 3, null, 60000);
      const places = await page.evaluate(() => document.querySelectorAll("#net svg g.place").length);
      assert.equal(places, netPlaceCount());
    });
    await page.close();
  } finally {
    await stopProcess(run);
  }
}

function recordLog() {
  const folder = join(outDir, "log_run");
  const result = runProgram(join(bin, "beft-run"),
    [scenario, "--max-ticks", String(LOG_TICKS), "--record-camera", "every:5", "--no-report", "--out", folder],
    { cwd: source, timeoutMs: 600000 });
  assert.equal(result.status, 0, result.output);
  return join(folder, "run.lcmlog");
}

// Seeks the log to halfway between the robot states of `tick` and the next
// (so that whether a seek takes in a message logged at that very time does
// not matter), and compares the page's robot and time with the log's.
async function seekAndCompare(page, states, tick, name) {
  const at = states.findIndex((s) => s.tick === tick);
  assert.ok(at >= 0 && at + 1 < states.length, `the log has no ROBOT_STATE of tick ${tick} and after`);
  const [expected, next] = [states[at], states[at + 1]];
  const timeNs = ((expected.logUtime + next.logUtime) / 2n) * 1000n;
  await page.evaluate((ns) => window.beft.actions.seek(ns), timeNs.toString());
  const state = await waitForState(page, (s, t) => s.robot && s.robot.tick === t, expected.tick, 60000);
  assert.equal(robotStateAt(states, BigInt(state.logTimeNs) / 1000n), expected, `page time ${state.logTimeNs} ns`);
  assert.ok(Math.abs(state.robot.x - expected.x) < 1e-6, `x ${state.robot.x} != ${expected.x}`);
  assert.ok(Math.abs(state.robot.y - expected.y) < 1e-6, `y ${state.robot.y} != ${expected.y}`);
  assert.ok(Math.abs(state.robot.yaw - expected.yaw) < 1e-6, `yaw ${state.robot.yaw} != ${expected.yaw}`);
  await screenshot(page, outDir, name);
  return state;
}

async function loggedRun(checks, browser) {
  const logPath = recordLog();
  const states = robotStates(readLogEvents(logPath));
  assert.ok(states.length > LOG_TICKS / 2, `${logPath}: ${states.length} robot states`);
  const port = await freePort();
  const bridge = startProcess(join(bin, "beft-bridge"), ["--log", logPath, "--port", String(port), "--net", defaultNet],
    { cwd: source, logFile: join(outDir, "log_bridge.out") });
  try {
    await waitForHttp(`http://127.0.0.1:${port}/`, bridge);
    const page = await openPage(browser, `http://127.0.0.1:${port}/`);
    await checks.run("log: the page knows it plays a log", async () => {
      await waitForState(page, (s) => s.connected && s.mode === "log", null, 60000);
      // The page shows its log controls at its next frame, after its state says "log".
      await page.waitForSelector("#playback-pause", { visible: true, timeout: 60000 });
      await page.click("#playback-pause");  // seeks and steps from a held log
    });
    await checks.run("log: seeking shows that time's robot pose and the scenario's objects", async () => {
      const state = await seekAndCompare(page, states, Math.floor(LOG_TICKS * 0.75), "log_seek_late");
      assert.equal(state.objectCount, scenarioObjectCount());
    });
    await checks.run("log: seeking back shows the earlier pose", async () => {
      await seekAndCompare(page, states, Math.floor(LOG_TICKS * 0.25), "log_seek_early");
    });
    await checks.run("log: the net is drawn with the marking where the log stands", async () => {
      const state = await waitForState(page, (s) => s.netDrawn && s.markingStep >= 0, null, 60000);
      const shown = await page.evaluate(() => document.querySelectorAll("#net svg g.marked, #net svg g.lit").length);
      assert.ok(shown > 0, `step ${state.markingStep}: no place marked, no transition lit`);
    });
    await checks.run("log: step plays exactly one tick on", async () => {
      const held = await heldTick(page);
      await page.click("#playback-step");
      await waitForState(page, (s, t) => s.tick === t + 1, held, 60000);
      assert.equal(await heldTick(page), held + 1);
      const expected = states.find((s) => s.tick === held + 1);
      const robot = (await pageState(page)).robot;
      assert.ok(Math.abs(robot.x - expected.x) < 1e-6 && Math.abs(robot.y - expected.y) < 1e-6, JSON.stringify(robot));
      assert.deepEqual(page.errors, []);
    });
    await page.close();
  } finally {
    await stopProcess(bridge);
  }
}

preconditions();
for (const folder of ["live_run", "log_run"]) rmSync(join(outDir, folder), { recursive: true, force: true });
mkdirSync(outDir, { recursive: true });
const checks = new Checks();
const browser = await launchBrowser();
try {
  if (part !== "log") await liveRun(checks, browser);
  if (part !== "live") await checks.run("log: a recorded yard run", () => loggedRun(checks, browser));
} finally {
  await browser.close();
}
checks.finish();
