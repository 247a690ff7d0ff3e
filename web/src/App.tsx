// The console shell: navigation and the hash router (one page module per route).
import { BatchPage } from "./pages/BatchPage";
import { Batches } from "./pages/Batches";
import { Compare } from "./pages/Compare";
import { Dashboard } from "./pages/Dashboard";
import { History } from "./pages/History";
import { TrialPage } from "./pages/TrialPage";
import { useHash } from "./lib/route";

export function App() {
  const hash = useHash();
  const [, page, a, b] = hash.split("/").map(decodeURIComponent);
  let view: React.ReactNode;
  if (page === "trial" && a) view = <TrialPage key={a} id={a} />;
  else if (page === "batch" && a) view = <BatchPage key={a} id={a} />;
  else if (page === "batches") view = <Batches />;
  else if (page === "history") view = <History />;
  else if (page === "compare" && a && b) view = <Compare key={`${a}/${b}`} a={a} b={b} />; // a new pair: a new page (no answer for the old pair lands on it)
  else view = <Dashboard />;
  return (
    <>
      <header>
        <strong>SPARK console</strong>
        <nav><a href="#/">Dashboard</a><a href="#/history">History</a><a href="#/batches">Batches</a><a href="/docs">API</a></nav>
      </header>
      <main>{view}</main>
    </>
  );
}
