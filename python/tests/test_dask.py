"""`symbody.dask.study` on a local Dask cluster of two worker processes: the same rows as the
local `symbody.study`, bit for bit, for a mechanism and a scene file given by a relative path;
no row lost when a worker process is killed mid-study; `import symbody` without Dask."""

import os
import signal
import subprocess
import sys

import numpy as np
import pytest

import symbody

distributed = pytest.importorskip("distributed")
pandas = pytest.importorskip("pandas")
import symbody.dask  # noqa: E402  (needs distributed: after the skip)

PARAMS = {"r": np.linspace(0.08, 0.12, 10), "len": np.linspace(0.33, 0.37, 10)}


@pytest.fixture(scope="module")
def client():
    # Processes, as on a real cluster: what the tasks need must pickle and be importable.
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as c:
        yield c


def same_rows(cluster_rows, local_rows):
    """Every column but the runs' own times equal, bit for bit (NaN equal to NaN)."""
    assert list(cluster_rows.columns) == list(local_rows.columns)
    pandas.testing.assert_frame_equal(
        cluster_rows.drop(columns="wall_s"), local_rows.drop(columns="wall_s"), check_exact=True
    )


def test_a_cluster_study_equals_the_local_one(client):
    local = symbody.study("slider_crank", PARAMS, t_end=0.3, jobs=2)
    # The default chunks (4 per worker thread: 8 chunks of 2 rows) and uneven ones (4+4+2).
    for chunk_size in (None, 4):
        rows = symbody.dask.study(client, "slider_crank", PARAMS, t_end=0.3, chunk_size=chunk_size)
        same_rows(rows, local)
    assert list(rows["run"]) == list(range(10)) and set(rows["status"]) == {"ok"}


def test_a_scene_file_a_dataframe_failed_rows_and_metrics(client, tmp_path, monkeypatch):
    scene = tmp_path / "four.toml"
    scene.write_text('mechanism = "four_bar"\n[time]\nend = 0.1\n')
    params = pandas.DataFrame({"b": [0.1, 0.35, 0.3, 0.1, 0.32]})
    # A relative path, from a folder the workers are not in: it must travel absolute.
    monkeypatch.chdir(tmp_path)
    local = symbody.study("four.toml", params)
    rows = symbody.dask.study(client, "four.toml", params, chunk_size=2)
    same_rows(rows, local)
    assert list(rows["status"]) == ["failed", "ok", "ok", "failed", "ok"]
    some = symbody.dask.study(client, "four.toml", params, metrics=["energy_balance"])
    same_rows(some, symbody.study("four.toml", params, metrics=["energy_balance"]))
    assert "energy_balance" in some and "max|Phi|" not in some


def test_wrong_names_raise_on_the_client_and_no_rows_is_an_empty_study(client):
    with pytest.raises(ValueError, match="did you mean `r`"):
        symbody.dask.study(client, "slider_crank", {"rr": [0.1]})
    with pytest.raises(ValueError, match="metrics"):
        symbody.dask.study(client, "slider_crank", {"r": [0.1]}, metrics=["nothing"])
    empty = symbody.dask.study(client, "slider_crank", {"r": []}, t_end=0.1)
    assert len(empty) == 0 and "max|motor|" in empty


def test_a_worker_killed_mid_study_loses_no_row(client):
    local = symbody.study("slider_crank", PARAMS, t_end=0.3, jobs=2)
    chunks = symbody.dask.split("slider_crank", PARAMS, t_end=0.3, chunk_size=2)
    gate = distributed.Event("symbody-test-gate", client=client)
    gate.clear()

    def gated(chunk):
        # Defined here so that it pickles by value (workers cannot import this test module).
        # Every chunk but the first waits for the gate, which opens only after the kill: the
        # kill comes before they finish, whatever the timing.
        import os

        import distributed
        import symbody.dask

        if chunk["start"] > 0 and not distributed.Event("symbody-test-gate").wait(timeout=60):
            raise TimeoutError("the gate never opened")
        return os.getpid(), symbody.dask.run_chunk(chunk)

    # The first chunk alone, then the rest: it is done, and held by a worker, while the
    # others wait at the gate on both workers.
    futures = [client.submit(gated, chunks[0], pure=False)]
    first = futures[0].result()
    futures += client.map(gated, chunks[1:], pure=False)
    pids = client.run(os.getpid)
    # The worker holding the first chunk's answer: killing it loses that answer (and the
    # chunk it is running), so Dask must run them again.
    (holder,) = client.who_has(futures[0])[futures[0].key]
    assert pids[holder] == first[0]
    assert not any(f.done() for f in futures[1:])
    os.kill(pids[holder], signal.SIGKILL)
    gate.set()
    answers = client.gather(futures)
    # The first chunk's answer came from another process than the one killed: computed again.
    assert answers[0][0] != first[0]
    client.wait_for_workers(2, timeout=60)
    assert first[0] not in client.run(os.getpid).values()
    parts = [part for _, part in answers]
    same_rows(symbody.dask.combine(parts), local)
    # The chunks' answers in any order (as_completed, say) make the same study.
    same_rows(symbody.dask.combine(parts[::-1]), local)


def test_import_symbody_needs_no_dask_and_symbody_dask_says_what_to_install():
    hide = (
        "import sys; sys.modules['distributed'] = None; sys.modules['dask'] = None\n"
        "import symbody\n"
        "try:\n    import symbody.dask\nexcept ImportError as e:\n    print(e)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", hide], capture_output=True, text=True, check=True
    ).stdout
    assert 'pip install "dask[distributed]"' in out
