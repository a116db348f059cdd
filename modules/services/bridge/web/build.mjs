// Bundles the viewer page: src/main.js and what it imports (three, fzstd)
// into one app.js beside index.html and style.css, so that the bridge serves
// three static files and the browser fetches nothing else.
//   node build.mjs --source WEB_DIR --out DIR --modules NODE_MODULES_DIR
// It runs from the folder where `npm ci` put node_modules (an ES module finds
// esbuild beside itself, not through NODE_PATH).
import { build } from "esbuild";
import { copyFileSync, mkdirSync } from "node:fs";
import { join } from "node:path";

function option(name) {
  const at = process.argv.indexOf(name);
  if (at < 0 || at + 1 >= process.argv.length) throw new Error(`missing ${name}`);
  return process.argv[at + 1];
}

const source = option("--source");
const out = option("--out");
const modules = option("--modules");
mkdirSync(out, { recursive: true });

await build({
  entryPoints: [join(source, "src", "main.js")],
  bundle: true,
  format: "iife",
  target: "es2020",
  minify: true,
  sourcemap: true,
  // node_modules live in the build tree, not beside the sources.
  nodePaths: [modules],
  outfile: join(out, "app.js"),
  logLevel: "warning",
});
for (const file of ["index.html", "style.css"]) copyFileSync(join(source, file), join(out, file));
