"""A fleet of fasteners through boltzone on a Dask cluster.

The fleet table (Parquet, or CSV) has one row per fastener and one column per dotted scene key
(`hole.radius`, `load.force`, `plates[0].thickness`, ...); its units, and the scene keys every
row shares, are in the table's metadata: the Parquet schema's key `boltzone` (JSON: `{"units":
..., "base": {...}}`), or for a CSV a first line `# boltzone: {JSON}`. Each partition is
solved by the plain function `boltzone.solve_many` (`dask.dataframe.map_partitions`), on a
`dask.distributed` cluster: a LocalCluster by default, or a scheduler address for a real one.
The results, with the `error` column of any failed row, are written as Parquet.

    python fleet_dask.py FLEET.parquet OUT.parquet [--scheduler tcp://host:8786] [--workers 2]
    python fleet_dask.py --make-fleet FLEET.parquet N    # a random fleet to try it on
"""

import argparse
import json
import random

import pandas as pd

import boltzone

META_KEY = b"boltzone"


def read_meta(path):
    """The fleet's metadata: `{"units": ..., "base": {...}}`."""
    path = str(path)
    if path.endswith(".parquet"):
        import pyarrow.parquet as pq

        meta = pq.read_schema(path).metadata or {}
        if META_KEY not in meta:
            raise ValueError("%s: no `boltzone` key in the Parquet metadata" % path)
        return json.loads(meta[META_KEY])
    with open(path) as f:
        first = f.readline()
    if not first.startswith("# boltzone:"):
        raise ValueError("%s: the first line must be `# boltzone: {JSON}`" % path)
    return json.loads(first.split(":", 1)[1])


def make_fleet(path, n, seed=1, units="mm-MPa-N"):
    """A random fleet of `n` single-plate fasteners (M5 to M12 class, mm, N) in `path`."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    rng = random.Random(seed)
    rows = []
    for _ in range(n):
        a = rng.uniform(2.5, 6.5)
        rows.append({"hole.radius": a, "load.outer_radius": a * rng.uniform(1.6, 2.2),
                     "load.force": rng.uniform(2e3, 4e4),
                     "plates[0].thickness": a * rng.uniform(0.5, 2.5),
                     "plates[0].material": rng.choice(["steel-1018", "aluminium-2024-t3",
                                                       "titanium-ti-6al-4v"])})
    meta = {"units": units, "base": {"model": "single-plate", "tolerance": 1e-3}}
    table = pa.Table.from_pandas(pd.DataFrame(rows), preserve_index=False)
    table = table.replace_schema_metadata({**(table.schema.metadata or {}),
                                           META_KEY: json.dumps(meta).encode()})
    pq.write_table(table, path)


def solve_fleet(fleet, out, client, partitions=None):
    """Solves the fleet table `fleet` on the cluster of `client`; writes Parquet to `out`
    (one file per partition) and returns the number of rows."""
    import dask.dataframe as dd

    meta = read_meta(fleet)
    base = dict(meta.get("base", {}), units=meta["units"])
    fleet = str(fleet)
    frame = dd.read_parquet(fleet) if fleet.endswith(".parquet") else dd.read_csv(
        fleet, comment="#")
    if partitions:
        frame = frame.repartition(npartitions=partitions)
    # the output's columns and dtypes: solve_many of an empty partition
    empty = boltzone.solve_many(frame._meta, base=base, progress=False)
    solved = frame.map_partitions(boltzone.solve_many, base=base, threads=1, progress=False,
                                  meta=empty)
    solved.to_parquet(out, write_index=False, compute=True)
    return len(pd.read_parquet(out))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("fleet")
    p.add_argument("out", nargs="?")
    p.add_argument("--make-fleet", type=int, metavar="N")
    p.add_argument("--scheduler", help="address of a running dask scheduler")
    p.add_argument("--workers", type=int, default=2, help="LocalCluster workers")
    p.add_argument("--partitions", type=int)
    a = p.parse_args(argv)
    if a.make_fleet:
        make_fleet(a.fleet, a.make_fleet)
        return
    from dask.distributed import Client, LocalCluster

    if a.scheduler:
        client = Client(a.scheduler)
    else:
        client = Client(LocalCluster(n_workers=a.workers, threads_per_worker=1))
    with client:
        n = solve_fleet(a.fleet, a.out, client, a.partitions)
    print("%d fasteners solved into %s" % (n, a.out))


if __name__ == "__main__":
    main()
