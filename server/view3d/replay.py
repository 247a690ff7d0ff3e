"""Replay a finished trial in the 3D view from its recorded scene states (qpos every 40 ms of simulated time).
The scene is rebuilt from the task and seed (scene construction is deterministic), then only forward
kinematics runs: no physics, so a replay shows exactly what was recorded."""

from __future__ import annotations

import itertools
import threading
import time

import numpy as np


class ReplayUnavailable(Exception):
    """The trial cannot be replayed (still running, no recorded states, or its task no longer exists)."""


def start_replay(store, scene, trial_id: str, speed: float = 1.0) -> dict:
    """Start replaying on a thread; raises KeyError for an unknown trial, ReplayUnavailable with the reason."""
    from spark_core import TASKS

    trial = store.get_trial(trial_id)
    if trial is None:
        raise KeyError(trial_id)
    if trial["status"] != "done":
        raise ReplayUnavailable(f"trial {trial_id!r} is {trial['status']}: replay needs a finished trial")
    states = store.scene_states(trial_id)
    if not states:
        raise ReplayUnavailable(
            f"trial {trial_id!r} has no recorded scene states (recorded before replay existed, "
            f"or it ended before the robot moved)"
        )
    task = TASKS.get(trial["task"])
    if task is None:
        raise ReplayUnavailable(f"trial {trial_id!r} ran task {trial['task']!r}, which this build does not have")
    keypoints = {g["label"]: g["keypoint"]["position_m"] for g in trial.get("groundings", []) if g.get("keypoint")}
    key = f"replay:{trial_id}"
    world = task.make_world(trial["seed"])
    if len(states[0][1]) != world.model.nq:
        world.close()
        raise ReplayUnavailable(
            f"trial {trial_id!r} was recorded with a different scene model "
            f"({len(states[0][1])} vs {world.model.nq} joint coordinates)"
        )
    threading.Thread(
        target=_play,
        args=(scene, key, trial_id, world, states, keypoints, speed),
        name=f"replay-{trial_id}",
        daemon=True,
    ).start()
    return {
        "id": trial_id,
        "key": key,
        "states": len(states),
        "speed": speed,
        "duration_s": round(states[-1][0] - states[0][0], 3),
    }


def _play(scene, key: str, trial_id: str, world, states: list, keypoints: dict, speed: float) -> None:
    import mujoco

    from spark_core import body_poses, visual_geoms

    m = world.model
    d = mujoco.MjData(m)
    origin = np.asarray(getattr(world, "origin_m", np.zeros(3)), float)  # robosuite/LIBERO: not MuJoCo's origin
    try:
        scene.show(key, visual_geoms(m), title=f"replay of {trial_id}")
        scene.markers(key, keypoints)
        t0, start, shown = states[0][0], time.monotonic(), -1.0
        for t, qpos in states:
            delay = (t - t0) / speed - (time.monotonic() - start)
            if delay > 0:
                time.sleep(delay)
            if scene.current != key:
                return  # a live trial (or another replay) took over the view
            xpos, xquat = body_poses(m, d, np.asarray(qpos, float))
            scene.update(key, xpos - origin, xquat)  # in the world's frame, like the live view and the keypoints
            if t - shown >= 0.5:
                scene.active(key, f"**Replay:** {trial_id}  \nt = {t:.1f} / {states[-1][0]:.1f} s (simulated)")
                shown = t
        scene.active(key, f"**Replay:** {trial_id}  \nfinished ({states[-1][0]:.1f} s simulated)")
    finally:
        world.close()


class ReplayCursors:
    """Show a finished trial in the 3D view at one instant (a page's time cursor): its recorded scene state at or
    before `t_sim_s`, and the keypoints grounded by then. Worlds of the last few trials stay built, so scrubbing
    costs one forward-kinematics pass per call."""

    def __init__(self, store, scene, keep: int = 2):
        self.store, self.scene, self.keep = store, scene, keep
        self._open: dict[str, dict] = {}  # trial id -> {world, data, states, times, groundings, origin}
        self._lock = threading.Lock()
        self._ticket_lock = threading.Lock()  # numbers are taken at once, not behind the (slow) replay lock
        # Focus requests in the order they reached the server: a page that moved on (another trial, or unbound)
        # has a later one, so an earlier seek still waiting for the lock (behind a camera render or a world
        # being built) must not draw its trial over the view the page now shows.
        self._tickets = itertools.count(1)
        self._latest = 0

    def ticket(self) -> int:
        """Number a focus request as it arrives; only the latest one's seek draws."""
        with self._ticket_lock:
            self._latest = next(self._tickets)
            return self._latest

    def seek(self, trial_id: str, t_sim_s: float, ticket: int | None = None) -> dict:
        """Raises KeyError for an unknown trial, ReplayUnavailable with the reason. With `ticket` (from
        ticket()), a seek that a later focus request overtook draws nothing (`superseded` in the answer)."""
        import bisect

        from spark_core import body_poses, visual_geoms

        key = f"replay:{trial_id}"
        if self.scene is None:
            raise ReplayUnavailable("the 3D view is off (SPARK_VISER=0)")
        with self._lock:
            r = self._open.get(trial_id) or self._load(trial_id)
            i = max(0, bisect.bisect_right(r["times"], t_sim_s) - 1)
            t, qpos = r["states"][i]
            if ticket is not None and ticket != self._latest:
                return {
                    "id": trial_id,
                    "key": key,
                    "t_sim_s": round(t, 3),
                    "index": i,
                    "states": len(r["states"]),
                    "superseded": True,
                }
            if self.scene.current != key:
                self.scene.show(key, visual_geoms(r["world"].model), title=f"replay of {trial_id}")
            self.scene.pinned = key
            xpos, xquat = body_poses(r["world"].model, r["data"], np.asarray(qpos, float))
            self.scene.update(key, xpos - r["origin"], xquat)
            grounded = {
                g["label"]: g["keypoint"]["position_m"]
                for g in r["groundings"]
                if g.get("keypoint") and (g.get("t_sim_s") or 0.0) <= t_sim_s
            }
            self.scene.markers(key, grounded)
            # the detection image of the grounding in effect (the latest at or before the cursor); trials stored
            # before per-grounding images have one, of the last grounding: shown from that time on
            j = bisect.bisect_right([t for t, _ in r["images"]], t_sim_s + 1e-9) - 1
            shown = r["images"][j][1] if j >= 0 else None
            if shown != r.get("shown") or self.scene.image_key != (None if shown is None else key):
                self.scene.image(key, None if shown is None else _read_rgb(shown))
                r["shown"] = shown
            self.scene.active(key, f"**Replay:** {trial_id}  \nt = {t:.2f} / {r['times'][-1]:.2f} s (simulated)")
        return {"id": trial_id, "key": key, "t_sim_s": round(t, 3), "index": i, "states": len(r["states"])}

    def camera_png(self, trial_id: str, camera: str | None, t_sim_s: float, width: int = 320) -> bytes:
        """PNG of `camera` (default: the scene's first) at the recorded state at or before `t_sim_s`, with the
        keypoints grounded by then drawn as crosses. Raises KeyError / ReplayUnavailable like seek, and
        ReplayUnavailable naming the cameras when `camera` is not one of the scene's."""
        import bisect

        import cv2
        import mujoco

        from spark_core import Keypoint, annotate

        with self._lock:
            r = self._open.get(trial_id) or self._load(trial_id)
            world = r["world"]
            m = world.model
            cameras = [m.camera(i).name for i in range(m.ncam)]
            if not cameras:
                raise ReplayUnavailable(f"trial {trial_id!r}: its scene has no camera")
            camera = camera or cameras[0]
            if camera not in cameras:
                raise ReplayUnavailable(f"trial {trial_id!r} has no camera {camera!r}; cameras: {', '.join(cameras)}")
            i = max(0, bisect.bisect_right(r["times"], t_sim_s) - 1)
            world.data.qpos[:] = np.asarray(r["states"][i][1], float)
            mujoco.mj_forward(m, world.data)  # kinematics only: the recorded state, no physics
            height = int(round(width * 3 / 4))
            frame = world.render(camera, width, height)
            kps = {
                g["label"]: Keypoint(
                    g["label"], np.asarray(g["keypoint"]["position_m"], float), np.asarray(g["keypoint"]["extent_m"])
                )
                for g in r["groundings"]
                if g.get("keypoint") and g["keypoint"].get("extent_m") and (g.get("t_sim_s") or 0.0) <= t_sim_s
            }
            img = annotate(frame, [], kps)
        ok, png = cv2.imencode(".png", cv2.cvtColor(img, cv2.COLOR_RGB2BGR))
        return png.tobytes()

    def _load(self, trial_id: str) -> dict:
        import mujoco

        from spark_core import TASKS

        trial = self.store.get_trial(trial_id)
        if trial is None:
            raise KeyError(trial_id)
        if trial["status"] != "done":
            raise ReplayUnavailable(f"trial {trial_id!r} is {trial['status']}: replay needs a finished trial")
        states = self.store.scene_states(trial_id)
        if not states:
            raise ReplayUnavailable(f"trial {trial_id!r} has no recorded scene states")
        task = TASKS.get(trial["task"])
        if task is None:
            raise ReplayUnavailable(f"trial {trial_id!r} ran task {trial['task']!r}, which this build does not have")
        world = task.make_world(trial["seed"])
        if len(states[0][1]) != world.model.nq:
            world.close()
            raise ReplayUnavailable(f"trial {trial_id!r} was recorded with a different scene model")
        while len(self._open) >= self.keep:
            self._open.pop(next(iter(self._open)))["world"].close()
        r = {
            "world": world,
            "data": mujoco.MjData(world.model),
            "states": states,
            "times": [s[0] for s in states],
            "groundings": trial.get("groundings", []),
            "origin": np.asarray(getattr(world, "origin_m", np.zeros(3)), float),
            "images": _grounding_images(trial),
        }
        self._open[trial_id] = r
        return r

    def forget(self, trial_id: str) -> None:
        """Drop a deleted or purged trial's built world: it must not be served from here any more."""
        with self._lock:
            r = self._open.pop(trial_id, None)
            if r is not None:
                r["world"].close()

    def close(self) -> None:
        with self._lock:
            for r in self._open.values():
                r["world"].close()
            self._open.clear()


def _grounding_images(trial: dict) -> list[tuple[float, str]]:
    """(simulated time, image path) of each grounding's first camera, by time; for a trial stored before
    per-grounding images, its first detection image at the time of its last grounding."""
    arts = trial.get("artifacts", [])
    per = {}
    for a in arts:
        if a.get("kind") == "grounding" and a.get("grounding") not in per:
            per[a["grounding"]] = (float(a.get("t_sim_s") or 0.0), str(a["path"]))
    if per:
        return sorted(per.values())
    entry = next((a for a in arts if a.get("kind") == "detections"), None)
    last = max((g.get("t_sim_s") or 0.0 for g in trial.get("groundings", [])), default=None)
    return [] if entry is None or last is None else [(float(last), str(entry["path"]))]


def _read_rgb(path: str, width: int = 320) -> np.ndarray | None:
    """An image file as RGB, `width` px wide, or None if it cannot be read."""
    import cv2

    img = cv2.imread(path)
    if img is None:
        return None
    h = int(round(img.shape[0] * width / img.shape[1]))
    return cv2.cvtColor(cv2.resize(img, (width, h), interpolation=cv2.INTER_AREA), cv2.COLOR_BGR2RGB)
