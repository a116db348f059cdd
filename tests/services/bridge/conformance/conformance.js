// The bridge against @foxglove/ws-protocol's client: a live yard run (beft-run
// --view on an LCM port of its own), then its log and a stored log played by
// beft-bridge --log. Exits 0 when every check holds, 1 otherwise.
//   node conformance.js BIN_DIR SOURCE_DIR WORK_DIR
"use strict";

const { spawn } = require("child_process");
const fs = require("fs");
const net = require("net");
const path = require("path");
const { Viewer, waitFor, check, failed, checkAdvertised } = require("./foxglove_checks");

const [binDir, sourceDir, workDir] = process.argv.slice(2);
const children = [];

function freePort() {
  return new Promise((resolve) => {
    const server = net.createServer();
    server.listen(0, "127.0.0.1", () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

// A program in the background, its output in a file (and kept for lines it waits for).
function start(program, args, outputFile) {
  const out = fs.openSync(outputFile, "w");
  const child = spawn(path.join(binDir, program), args, { stdio: ["ignore", "pipe", "pipe"] });
  child.output = "";
  const keep = (chunk) => { child.output += chunk; fs.writeSync(out, chunk); };
  child.stdout.on("data", keep);
  child.stderr.on("data", keep);
  child.exited = new Promise((resolve) => child.on("exit", (code) => resolve(code)));
  children.push(child);
  return child;
}

async function logChecks(log, label) {
  const port = await freePort();
  const bridge = start("beft-bridge", ["--log", log, "--port", String(port), "--paused", "--lcm-url", "memq://"],
                       path.join(workDir, `bridge-${label}.log`));
  await waitFor(`the bridge on ${label} to listen`, 60, () => bridge.output.includes("view: http://"));
  const viewer = await new Viewer(`ws://127.0.0.1:${port}/`).open();
  await waitFor("serverInfo", 10, () => viewer.serverInfo !== null);
  console.log(`-- ${label}: ${viewer.channels.size} topics`);
  checkAdvertised(viewer);
  check(viewer.serverInfo.capabilities.includes("time"), `${label}: serverInfo offers time`);
  for (const topic of ["ROBOT_STATE", "/scene", "/camera/color", "/tf", "GT_OBJECTS"]) viewer.subscribe(topic);
  const start_ns = BigInt(viewer.serverInfo.metadata.start_ns);
  viewer.publish("/beft/playback", { action: "play", speed: 4 });
  await waitFor("robot states, the scene and a colour image", 30,
                () => viewer.latest("ROBOT_STATE") && viewer.latest("/scene") && viewer.latest("/camera/color"));
  check(typeof viewer.latest("ROBOT_STATE").x === "number", `${label}: ROBOT_STATE decodes, x = ${viewer.latest("ROBOT_STATE").x}`);
  check(Array.isArray(viewer.latest("/scene").entities) && viewer.latest("/scene").entities.length > 0,
        `${label}: /scene holds ${viewer.latest("/scene").entities.length} entities`);
  const image = viewer.latest("/camera/color");
  check(image.encoding === "rgb8" && Buffer.from(image.data, "base64").length === image.width * image.height * 3,
        `${label}: /camera/color is an rgb8 image of ${image.width} x ${image.height}`);
  check(viewer.times.length > 0 && viewer.times[viewer.times.length - 1] >= start_ns, `${label}: Time frames in log time`);
  viewer.publish("/beft/playback", { action: "pause" });  // paused, the time stays where the seek put it
  viewer.publish("/beft/playback", { action: "seek", time_ns: Number(start_ns) });
  await waitFor("the time of the seek", 10, () => viewer.times.includes(start_ns));
  check(true, `${label}: seek answered with a Time frame at the log's start`);
  const statuses = viewer.statuses.length;
  viewer.publish("/beft/playback", { action: "fly" });
  viewer.publish("/beft/task", { action: "goto", x: 1, y: 2 });
  await waitFor("two error statuses", 10, () => viewer.statuses.length >= statuses + 2);
  const errors = viewer.statuses.slice(statuses).filter((s) => s.level === 2).map((s) => s.message);
  check(errors.some((m) => m.includes("fly")), `${label}: a bad playback control is answered: ${errors[0]}`);
  check(errors.some((m) => m.includes("takes no tasks")), `${label}: a task to a log is refused: ${errors[1]}`);
  viewer.close();
  bridge.kill("SIGTERM");
  check((await bridge.exited) === 0, `${label}: the bridge stops cleanly`);
}

// A goto the viewer publishes: pushed onto the run's task stack, as TASK_EVENTS and TASK_STACK say.
async function gotoChecks(viewer) {
  const robot = viewer.latest("ROBOT_STATE");
  viewer.publish("/beft/task", { action: "goto", x: robot.x + 1.0, y: robot.y, yaw: 0 });
  const fromViewer = (e) => e.task.origin === "viewer";
  await waitFor("TASK_EVENTS naming the viewer's goto", 120, () =>
    (viewer.messages.get("TASK_EVENTS") || []).some((m) => m.json.events.some(fromViewer)));
  const events = (viewer.messages.get("TASK_EVENTS") || []).flatMap((m) => m.json.events.filter(fromViewer));
  check(events.some((e) => e.event === 0 && e.task.kind === "goto"), "live: the viewer's goto was pushed");
  await waitFor("the goto on TASK_STACK, or finished", 120, () =>
    (viewer.messages.get("TASK_STACK") || []).some((m) => m.json.tasks.some((t) => t.origin === "viewer")) ||
    (viewer.messages.get("TASK_EVENTS") || []).some((m) => m.json.events.some((e) => fromViewer(e) && e.event >= 5)));
  check(true, "live: the run took the viewer's goto (TASK_STACK / TASK_EVENTS)");
  const statuses = viewer.statuses.length;
  viewer.publish("/beft/task", { action: "goto", x: "east" });
  await waitFor("an error status", 10, () => viewer.statuses.slice(statuses).some((s) => s.level === 2));
  check(true, `live: a bad task is answered: ${viewer.statuses.slice(statuses).find((s) => s.level === 2).message}`);
}

async function liveChecks() {
  const port = await freePort();
  const out = path.join(workDir, "run");
  const run = start("beft-run", [path.join(sourceDir, "scenarios/yard.xml"), "--view", "--port", String(port), "--fast",
                                 "--max-ticks", "400", "--no-report", "--out", out], path.join(workDir, "run.out"));
  await waitFor("beft-run to print the viewer's URL", 120, () => run.output.includes(`view: http://127.0.0.1:${port}/`));
  const viewer = await new Viewer(`ws://127.0.0.1:${port}/`).open();
  await waitFor("serverInfo", 10, () => viewer.serverInfo !== null);
  console.log(`-- live yard run: ${viewer.channels.size} topics`);
  checkAdvertised(viewer);
  for (const topic of ["ROBOT_STATE", "/scene", "/camera/color", "/tf", "TASK_EVENTS", "TASK_STACK"]) viewer.subscribe(topic);
  await waitFor("robot states, the scene and a colour image", 120,
                () => viewer.latest("ROBOT_STATE") && viewer.latest("/scene") && viewer.latest("/camera/color"));
  check(typeof viewer.latest("ROBOT_STATE").tick === "number", `live: ROBOT_STATE decodes (tick ${viewer.latest("ROBOT_STATE").tick})`);
  check(viewer.latest("/scene").entities.some((e) => e.id === "robot"), "live: /scene shows the robot");
  check(viewer.latest("/camera/color").encoding === "rgb8", "live: /camera/color is rgb8");
  check(viewer.latest("/tf").transforms.length >= 2, "live: /tf holds the robot's frames");
  await gotoChecks(viewer);
  viewer.close();
  const code = await run.exited;
  check(code === 0, `live: beft-run ended with ${code}`);
  return path.join(out, "run.lcmlog");
}

async function main() {
  fs.mkdirSync(workDir, { recursive: true });
  await logChecks(path.join(sourceDir, "tests/system/data/peek_6_ticks.lcmlog"), "peek_6_ticks.lcmlog");
  const recorded = await liveChecks();
  await logChecks(recorded, "the live run's log");
  console.log(failed() ? `${failed()} check(s) failed` : "every check holds");
  return failed() ? 1 : 0;
}

main()
  .then((code) => { process.exitCode = code; })
  .catch((error) => { console.error(`FAIL ${error.message}`); process.exitCode = 1; })
  .finally(() => { for (const child of children) if (child.exitCode === null) child.kill("SIGTERM"); });
