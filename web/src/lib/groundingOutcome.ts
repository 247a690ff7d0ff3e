// What became of one grounding (a label resolved through the cameras), as the trial page's camera panel says it
// after the grounding's time.
import type { Grounding } from "../api/types";

/** Nothing when a keypoint was kept; otherwise why not: ambiguous (one camera singled the label out while
 * another saw several of it) or nothing found. */
export function groundingOutcome(g: Pick<Grounding, "keypoint" | "several">): string {
  if (g.keypoint) return "";
  return g.several ? ` · ambiguous: one camera saw one, another ${g.several}` : " · no keypoint";
}
