// The viewer page for beft-bench-view: headless Chromium (Debian's chromium,
// WebGL through SwiftShader) opens --url as soon as it is served and prints
// what the page says about itself (window.beft) every --every-ms, one line
// each, until --seconds have passed (0: until SIGTERM or SIGINT).
//   node page_probe.mjs --url http://127.0.0.1:PORT/ [--every-ms 1000] [--seconds 0]
//   node page_probe.mjs --check    (starts the browser, prints its version, ends)
// Lines: "browser: VERSION", "connected: WALL_MS TICK", "sample: WALL_MS TICK
// FRAME_TIME_MS FRAMES RENDERS OBJECTS HYPOTHESES CONNECTED", "page error:
// TEXT"; "unavailable: REASON" and exit 77 when chromium or puppeteer-core
// is missing.
import { existsSync } from "node:fs";

const UNAVAILABLE = 77;

function option(name, fallback) {
  const at = process.argv.indexOf(name);
  return at >= 0 && at + 1 < process.argv.length ? process.argv[at + 1] : fallback;
}

function unavailable(reason) {
  console.log(`unavailable: ${reason}`);
  process.exit(UNAVAILABLE);
}

const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

async function launchBrowser() {
  const executablePath = [process.env.BEFT_CHROMIUM, "/usr/bin/chromium", "/usr/bin/chromium-browser"].find(
    (path) => path && existsSync(path));
  if (!executablePath) unavailable("chromium is not installed (Debian package chromium)");
  let puppeteer;
  try {
    puppeteer = (await import("puppeteer-core")).default;
  } catch (error) {
    unavailable(`npm package puppeteer-core is not installed (npm ci in the bench's build folder): ${error.message}`);
  }
  return puppeteer.launch({
    executablePath,
    headless: true,
    // A person's browser has no debugger attached. Puppeteer's network
    // monitor would have Chromium send every WebSocket frame the page
    // receives to node over the DevTools protocol (base64, as JSON): work
    // on the run's cores that watching does not cost.
    networkEnabled: false,
    issuesEnabled: false,
    // WebGL by SwiftShader, the page composited in software: what Chromium
    // does on a machine without a GPU (--ignore-gpu-blocklist would have it
    // composite every frame through SwiftShader's GL instead, at several
    // times the CPU, which no browser there does by itself).
    args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-gpu-compositing",
      "--window-size=1400,900"],
    defaultViewport: { width: 1400, height: 900 },
  });
}

// Polls until the page is served (the run's processes are still starting).
async function waitUntilServed(url, stopping) {
  while (!stopping()) {
    try {
      if ((await fetch(url)).ok) return true;
    } catch {
      // not listening yet
    }
    await sleep(50);
  }
  return false;
}

const readState = (page) => page.evaluate(() => {
  const s = window.beft || {};
  return [s.tick, s.frameTimeMs, s.frames, s.renders, s.objectCount, s.hypothesisCount, s.connected];
});

async function probe(url, everyMs, seconds) {
  let stop = false;
  for (const signal of ["SIGTERM", "SIGINT"]) process.on(signal, () => (stop = true));
  const browser = await launchBrowser();
  try {
    console.log(`browser: ${await browser.version()}`);
    const page = await browser.newPage();
    page.on("pageerror", (error) => console.log(`page error: ${error}`));
    if (!(await waitUntilServed(url, () => stop))) return;
    await page.goto(url, { waitUntil: "load" });
    await page.waitForFunction(() => window.beft && window.beft.connected, { timeout: 60000, polling: 20 });
    console.log(`connected: ${Date.now()} ${(await readState(page))[0]}`);
    const until = seconds > 0 ? Date.now() + seconds * 1000 : Infinity;
    while (!stop && Date.now() < until) {
      await sleep(everyMs);
      const values = await readState(page);
      console.log(`sample: ${Date.now()} ${values.join(" ")}`);
    }
  } finally {
    await browser.close();
  }
}

if (process.argv.includes("--check")) {
  const browser = await launchBrowser();
  console.log(`browser: ${await browser.version()}`);
  await browser.close();
} else {
  await probe(option("--url"), Number(option("--every-ms", "1000")), Number(option("--seconds", "0")));
}
