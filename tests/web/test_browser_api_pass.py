"""Pages that show what the adversarial API pass's fixes changed in the API's answers, in a real browser (the
fixtures of test_browser.py: uvicorn with trial workers, Debian's headless chromium)."""

from __future__ import annotations

from zoneinfo import ZoneInfo

from .test_browser import APPS, browser, page, server, shot  # noqa: F401 (fixtures)


def _store():
    return APPS[-1].state.store


def test_a_task_with_no_judged_trial_shows_no_rate_and_no_interval(server, page):  # noqa: F811
    """A batch task whose trials were all aborted has no success rate and no interval (the API said ci95 [0, 0]
    beside success_rate null: the table showed '0.0 % – 0.0 %' and the chart an error bar pinned at 0 %)."""
    store = _store()
    store.create_batch("batch-unjudged", {"suite": "builtin", "trial_count": 2})
    for n, (task, verdict) in enumerate((("lift_block", "aborted"), ("push_to_zone", "success"))):
        store.create_trial(
            f"batch-unjudged-{n:04d}-{task}-0",
            status="done",
            task=task,
            verdict=verdict,
            outcome="success" if verdict == "success" else "aborted",
            success=verdict == "success",
            batch_id="batch-unjudged",
        )
    errors: list[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(f"{server}/#/batch/batch-unjudged")
    page.wait_for_selector("#batch-table tbody tr[data-task=lift_block]")
    page.wait_for_selector("#success-chart canvas")
    unjudged = page.locator("#batch-table tr[data-task=lift_block]")
    assert unjudged.locator("td.rate").inner_text() == "–"
    assert unjudged.locator("td.ci95").inner_text() == "–"
    judged = page.locator("#batch-table tr[data-task=push_to_zone]")
    assert judged.locator("td.rate").inner_text() == "100.0 %"
    assert judged.locator("td.ci95").inner_text().endswith("– 100.0 %")
    page.wait_for_timeout(300)  # the chart's draw hook has run
    assert not errors, errors  # the chart skips the task's whisker instead of reading a null interval
    shot(page, "batch-unjudged")


LEFT_PICK = """task: lift the red block with the left arm
tree:
  type: sequence
  children:
    - type: pick
      arm: left
      params: {keypoint_label: red block}
"""


def test_your_own_plans_arm_tags_are_checked_against_the_chosen_robot(server, page):  # noqa: F811
    """The plan editor validates against the robot the form will run: `arm: left` on lift_block's default (the
    one-arm Panda) is an error on its line and Run is off (the server would refuse it with a 422); on the
    bimanual set-up the same plan is valid."""
    page.goto(server + "/")
    page.click("button[data-task=lift_block]")
    page.click("#new-trial summary:has-text('Run your own plan')")
    page.fill("#new-trial textarea[name=plan]", LEFT_PICK)
    page.wait_for_selector("#plan-errors li")
    line = page.locator(".plan-lines li.error-line")
    assert line.get_attribute("data-path") == "tree.children[0].arm"
    assert "its arms: right" in line.inner_text()
    assert not page.is_enabled("#new-trial button[type=submit]")
    page.select_option("#new-trial select[name=embodiment]", "bimanual")
    page.wait_for_selector("#plan-ok")
    assert page.is_enabled("#new-trial button[type=submit]")
    page.select_option("#new-trial select[name=embodiment]", "ur10")
    page.wait_for_selector("#plan-errors li:has-text('the ur10 embodiment has no such arm')")


def test_a_capbench_plans_arm_tags_are_checked_against_its_robosuite_panda(server, page):  # noqa: F811
    """The CaP-Bench and LIBERO-PRO robots are in the catalog: the editor checks a plan for Lift against
    robosuite's one Panda (it was not checked, and the server queued it), and the robot choice offers the task's
    own robot only."""
    page.goto(server + "/")
    page.click("details[data-suite=capbench] summary")
    page.click("button[data-task=Lift]")
    page.wait_for_selector("#task-card[data-task=Lift]")
    options = page.locator("#new-trial select[name=embodiment] option")
    assert options.evaluate_all("os => os.map(o => o.value)") == ["", "robosuite-panda"]
    page.click("#new-trial summary:has-text('Run your own plan')")
    page.fill("#new-trial textarea[name=plan]", LEFT_PICK)
    page.wait_for_selector("#plan-errors li:has-text('the robosuite-panda embodiment has no such arm')")
    assert page.locator(".plan-lines li.error-line").get_attribute("data-path") == "tree.children[0].arm"
    assert not page.is_enabled("#new-trial button[type=submit]")


def test_times_are_shown_in_the_browsers_time_zone(server, browser):  # noqa: F811
    """The API serves created_at in UTC with its offset; the history, the batch list and the batch page show it
    in the browser's zone (they showed the first 19 characters of the text: UTC, unmarked, as if local)."""
    from datetime import UTC, datetime

    store = _store()
    store.create_batch("batch-zoned", {"suite": "builtin", "trial_count": 1})
    store.create_trial(
        "zoned-trial",
        task="lift_block",
        instruction="zoned: lift the red block",
        status="done",
        batch_id="batch-zoned",
        created_at=datetime(2026, 1, 2, 3, 4, 5, tzinfo=UTC),
    )
    ctx = browser.new_context(viewport={"width": 1400, "height": 1000}, timezone_id="Asia/Kolkata")  # UTC+05:30
    try:
        pg = ctx.new_page()
        pg.goto(f"{server}/#/history")
        pg.fill("input[name=q]", "zoned")  # its instruction: the one row, whatever else the history holds
        row = pg.locator("tr[data-id=zoned-trial]")
        row.wait_for()
        assert row.locator("td[data-col=date]").inner_text() == "2026-01-02 08:34:05"
        pg.goto(f"{server}/#/batches")
        created = pg.locator("#batch-list tr[data-id=batch-zoned] td.created")
        created.wait_for()
        stamp = store.get_batch("batch-zoned")["created_at"]
        local = datetime.fromisoformat(stamp).astimezone(ZoneInfo("Asia/Kolkata")).strftime("%Y-%m-%d %H:%M:%S")
        assert created.inner_text() == local, (stamp, created.inner_text())
        pg.goto(f"{server}/#/batch/batch-zoned")
        pg.wait_for_selector("#batch-settings")
        assert f"created {local}" in pg.locator("#batch-settings").inner_text()
        assert pg.locator("#batch-trials tr[data-id=zoned-trial] td[data-col=date]").inner_text() == (
            "2026-01-02 08:34:05"
        )
    finally:
        ctx.close()
