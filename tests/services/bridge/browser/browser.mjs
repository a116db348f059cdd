// What the viewer's browser tests share: headless Chromium (Debian's
// chromium package, WebGL through SwiftShader), waiting on the page's own
// state (window.beft), screenshots as artefacts, and a small runner that
// prints "N passed, N failed" and exits 77 when something needed is missing.
import { existsSync, mkdirSync } from "node:fs";
import { createServer } from "node:net";
import { join } from "node:path";

export const SKIP = 77;

export function skip(reason) {
  console.log(`SKIPPED: ${reason}`);
  process.exit(SKIP);
}

export function option(name, fallback) {
  const at = process.argv.indexOf(name);
  return at >= 0 && at + 1 < process.argv.length ? process.argv[at + 1] : fallback;
}

export function chromiumPath() {
  const candidates = [process.env.BEFT_CHROMIUM, "/usr/bin/chromium", "/usr/bin/chromium-browser"];
  return candidates.find((path) => path && existsSync(path));
}

// puppeteer-core from this folder's package-lock.json, installed by `npm ci`
// in the build tree; a missing one skips the test.
export async function loadPuppeteer() {
  try {
    return (await import("puppeteer-core")).default;
  } catch (error) {
    skip(`npm package puppeteer-core is not installed (npm ci in the test's build folder): ${error.message}`);
  }
}

export async function launchBrowser() {
  const executablePath = chromiumPath();
  if (!executablePath) skip("chromium is not installed (Debian package chromium)");
  const puppeteer = await loadPuppeteer();
  return puppeteer.launch({
    executablePath,
    headless: true,
    args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
      "--window-size=1400,900"],
    defaultViewport: { width: 1400, height: 900 },
  });
}

// Opens the page and collects its console errors in page.errors.
export async function openPage(browser, url) {
  const page = await browser.newPage();
  page.errors = [];
  page.on("pageerror", (error) => page.errors.push(String(error)));
  page.on("console", (message) => {
    if (message.type() === "error") page.errors.push(message.text());
  });
  await page.goto(url, { waitUntil: "load" });
  return page;
}

// Waits until predicate(window.beft, arg) holds in the page; returns the state then.
export async function waitForState(page, predicate, arg = null, timeoutMs = 60000) {
  const source = predicate.toString();
  await page.waitForFunction(
    (text, value) => {
      const test = (0, eval)(`(${text})`);
      return window.beft && test(window.beft, value);
    },
    { timeout: timeoutMs, polling: 100 },
    source,
    arg,
  );
  return pageState(page);
}

// A copy of window.beft without its functions.
export function pageState(page) {
  return page.evaluate(() => JSON.parse(JSON.stringify({ ...window.beft, actions: undefined })));
}

export async function screenshot(page, dir, name) {
  mkdirSync(dir, { recursive: true });
  const path = join(dir, `${name}.png`);
  await page.screenshot({ path });
  console.log(`screenshot: ${path}`);
  return path;
}

export function freePort() {
  return new Promise((resolve, reject) => {
    const server = createServer();
    server.once("error", reject);
    server.listen(0, "127.0.0.1", () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

export function sleep(ms) {
  return new Promise((resolve) => setTimeout(resolve, ms));
}

// Runs named checks in order; a failed check is reported and the rest go on.
export class Checks {
  constructor() {
    this.passed = 0;
    this.failed = 0;
  }

  async run(name, body) {
    try {
      await body();
      this.passed++;
      console.log(`[ PASSED ] ${name}`);
    } catch (error) {
      this.failed++;
      console.log(`[ FAILED ] ${name}: ${error && error.stack ? error.stack : error}`);
    }
  }

  finish() {
    console.log(`${this.passed} passed, ${this.failed} failed`);
    process.exitCode = this.failed ? 1 : 0;
  }
}
