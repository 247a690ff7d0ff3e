"""Issue 20: a fuzz pass over the OpenAPI schema (schemathesis): every operation, valid and invalid inputs, and no
answer is a 5xx. Bounded: a fixed number of examples per operation, no deadline per example (the machine is
shared), well under a minute in all.

The console has no worker slots here (workers=0): trials and batches the fuzzer manages to create are checked
and recorded as queued, as on a real console, but never run. The rate limit is lifted so that requests reach
the routes instead of being answered 429. schemathesis runs the app's lifespan itself (and ends it with the
test); the schema is built at import because its fixture-based loader does not run under pytest 9."""

import atexit
import shutil
import tempfile
from pathlib import Path

import pytest
import schemathesis
from hypothesis import HealthCheck, Phase, settings
from schemathesis.checks import not_a_server_error

from server.app import create_app
from server.settings import Settings

EXAMPLES_PER_OPERATION = 40

_tmp = Path(tempfile.mkdtemp(prefix="spark-fuzz-"))
atexit.register(shutil.rmtree, _tmp, ignore_errors=True)
app = create_app(
    Settings(
        store_url=f"sqlite:///{_tmp / 'fuzz.db'}",
        workers=0,
        viser=False,
        artifacts_dir=str(_tmp / "art"),
        exports_dir=str(_tmp / "exports"),
        rate_per_s=1e9,
        rate_burst=1e9,
    )
)
schema = schemathesis.openapi.from_asgi("/openapi.json", app)


@pytest.mark.timeout(120)
@schema.parametrize()
@settings(
    max_examples=EXAMPLES_PER_OPERATION,
    deadline=None,
    derandomize=True,  # the same examples on every run: a failure in CI reproduces locally
    phases=[Phase.explicit, Phase.generate],
    suppress_health_check=list(HealthCheck),
)
def test_no_operation_answers_a_server_error(case):
    case.call_and_validate(checks=[not_a_server_error])
