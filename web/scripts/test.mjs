// `npm test`: bundle each tests/*.test.ts with esbuild (Vite's own) and run it with node's test runner.
import { spawnSync } from "node:child_process";
import { mkdirSync, readdirSync } from "node:fs";
import { join } from "node:path";
import { buildSync } from "esbuild";

const out = join("node_modules", ".cache", "spark-tests"); // inside the project: externals resolve from node_modules
mkdirSync(out, { recursive: true });
const files = readdirSync("tests").filter((f) => f.endsWith(".test.ts"));
for (const f of files) {
  buildSync({ entryPoints: [join("tests", f)], bundle: true, platform: "node", format: "esm", outfile: join(out, f.replace(/\.ts$/, ".mjs")),
    external: ["uplot", "react", "react-dom", "react-resizable-panels"], jsx: "automatic", loader: { ".css": "empty" }, logLevel: "error" });
}
const r = spawnSync(process.execPath, ["--test", ...files.map((f) => join(out, f.replace(/\.ts$/, ".mjs")))], { stdio: "inherit" });
process.exit(r.status ?? 1);
