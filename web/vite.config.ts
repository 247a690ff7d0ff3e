// Vite build of the console (served by FastAPI from web/dist). Swagger UI's assets are copied next to it so
// /docs works offline.
import { cpSync, mkdirSync } from "node:fs";
import { createRequire } from "node:module";
import { dirname, resolve } from "node:path";
import react from "@vitejs/plugin-react";
import { defineConfig, type Plugin } from "vite";

const require = createRequire(import.meta.url);

function swaggerAssets(): Plugin {
  return {
    name: "swagger-ui-assets",
    apply: "build",
    closeBundle() {
      const from = dirname(require.resolve("swagger-ui-dist/package.json"));
      const to = resolve(__dirname, "dist/swagger");
      mkdirSync(to, { recursive: true });
      for (const f of ["swagger-ui-bundle.js", "swagger-ui.css"]) cpSync(resolve(from, f), resolve(to, f));
    },
  };
}

export default defineConfig({
  plugins: [react(), swaggerAssets()],
  build: { outDir: "dist", emptyOutDir: true, chunkSizeWarningLimit: 1500 },
  server: { proxy: { "/api": { target: "http://127.0.0.1:8000", ws: true }, "/viser": { target: "http://127.0.0.1:8000", ws: true } } },
});
