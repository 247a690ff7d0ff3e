"""The learned instruction reader: the rules planner's fallback when its rule readings refuse an instruction whose
every phrase perception found. It enumerates the goals the found things afford (`candidates`), says each plainly,
and a cross-encoder trained on the dev corpus (`scorer`) picks the one the instruction states."""
