// The programs the system test starts (beft-run, beft-bridge): each in a
// process group of its own with its output in a file, stopped by that group.
import { spawn, spawnSync } from "node:child_process";
import { openSync } from "node:fs";
import { sleep } from "./browser.mjs";

export function startProcess(program, args, { cwd, logFile }) {
  const out = openSync(logFile, "a");
  const child = spawn(program, args, { cwd, detached: true, stdio: ["ignore", out, out] });
  child.exited = new Promise((resolve) => child.on("exit", (code, signal) => resolve({ code, signal })));
  child.running = true;
  child.exited.then(() => (child.running = false));
  return child;
}

// SIGINT to the group (a run writes its folder and stops its processes),
// SIGKILL after `graceMs`.
export async function stopProcess(child, graceMs = 20000) {
  if (!child || !child.running) return;
  try {
    process.kill(-child.pid, "SIGINT");
  } catch {
    return;
  }
  const outcome = await Promise.race([child.exited, sleep(graceMs).then(() => null)]);
  if (outcome === null) {
    try {
      process.kill(-child.pid, "SIGKILL");
    } catch {
      // already gone
    }
    await child.exited;
  }
}

// Runs a program to its end; returns {status, output}.
export function runProgram(program, args, { cwd, timeoutMs }) {
  const result = spawnSync(program, args, { cwd, encoding: "utf8", timeout: timeoutMs });
  return { status: result.status, output: `${result.stdout || ""}${result.stderr || ""}` };
}

// Waits until the page is served at `url`, or the process ends.
export async function waitForHttp(url, child, timeoutMs = 120000) {
  const until = Date.now() + timeoutMs;
  while (Date.now() < until) {
    if (child && !child.running) throw new Error(`${url}: the process serving it ended`);
    try {
      const response = await fetch(url);
      if (response.ok) return;
    } catch {
      // not listening yet
    }
    await sleep(250);
  }
  throw new Error(`${url}: not served within ${timeoutMs / 1000} s`);
}
