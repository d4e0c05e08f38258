"""The examples run: the notebook cells (Table 1, a matplotlib plot, the VTU read by meshio)
and the Dask fleet on a 2-worker LocalCluster, whose Parquet pandas reads back with the same
rows as solve_many."""

import json
import runpy
import sys
from pathlib import Path

import pandas as pd
import pytest

import boltzone

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def test_notebook_cells_run(tmp_path, monkeypatch):
    monkeypatch.setattr(sys, "argv", ["notebook.py", str(tmp_path)])
    runpy.run_path(str(EXAMPLES / "notebook.py"), run_name="__main__")
    assert (tmp_path / "interface_pressure.png").stat().st_size > 1000
    csv = pd.read_csv(tmp_path / "interface.csv")
    assert list(csv.columns) == ["r [in]", "p [psi]", "g [in]", "tau [psi]"]
    assert (tmp_path / "field.vtu").exists()


def test_dask_fleet_on_two_workers_equals_solve_many(tmp_path):
    pytest.importorskip("dask.distributed")
    sys.path.insert(0, str(EXAMPLES))
    try:
        import fleet_dask
    finally:
        sys.path.pop(0)
    from dask.distributed import Client, LocalCluster

    fleet, out = tmp_path / "fleet.parquet", tmp_path / "solved.parquet"
    fleet_dask.make_fleet(fleet, 60)
    # one bad fastener: a negative thickness must come back as a row with its error
    frame = pd.read_parquet(fleet)
    frame.loc[5, "plates[0].thickness"] = -1.0
    import pyarrow as pa
    import pyarrow.parquet as pq

    meta = fleet_dask.read_meta(fleet)
    table = pa.Table.from_pandas(frame, preserve_index=False)
    pq.write_table(table.replace_schema_metadata(
        {**table.schema.metadata, fleet_dask.META_KEY: json.dumps(meta).encode()}), fleet)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        n = fleet_dask.solve_fleet(fleet, out, client, partitions=4)
    assert n == 60
    got = pd.read_parquet(out)
    want = boltzone.solve_many(frame, base=dict(meta["base"], units=meta["units"]),
                               progress=False)
    assert list(got.columns) == list(want.columns)
    assert got["units"].dropna().unique().tolist() == ["mm-MPa-N"]
    assert got["error"].notna().sum() == 1 and "plates[0].thickness" in got["error"][5]
    for col in ["r_o", "r_o_error", "converged", "method", "error"]:
        a, b = got[col].tolist(), want[col].tolist()
        assert [None if pd.isna(x) else x for x in a] == [None if pd.isna(x) else x for x in b], col
