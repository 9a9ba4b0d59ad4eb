"""A `flapwright` sweep distributed over a Dask cluster (issue 39).

Usage:
    python examples/dask/sweep.py SCENE KEY=START:STOP:STEP [SCHEDULER_ADDRESS] [SHARDS]

Without an address, a LocalCluster of two single-threaded workers on this machine; with
one (``tcp://scheduler:8786``), the same code on that cluster, whose workers must have the
package installed (``pip install .``) and the scene's airfoil files at the same path. The
sweep is cut into shards (``shard="I/N"``: every N-th variant), one Dask task each; the
rows keep their variant index, so the shards' tables concatenated and sorted are the
table ``flapwright sweep`` writes. Each task designs its variants on the threads its worker
gives it (a worker of one thread: one variant at a time).
"""

import sys

import pandas

import flapwright


def sweep_on(client, scene, vary, shards):
    """The sweep's table, its shards run as Dask tasks on ``client``'s cluster."""
    futures = [
        client.submit(flapwright.sweep, scene, vary=vary, shard=f"{i}/{shards}", pure=False)
        for i in range(1, shards + 1)
    ]
    parts = client.gather(futures)
    return pandas.concat(parts).sort_values("variant").reset_index(drop=True)


def main():
    from dask.distributed import Client, LocalCluster

    scene, vary = sys.argv[1], sys.argv[2]
    address = sys.argv[3] if len(sys.argv) > 3 else None
    shards = int(sys.argv[4]) if len(sys.argv) > 4 else 8
    if address:
        client = Client(address)
    else:
        client = Client(LocalCluster(n_workers=2, threads_per_worker=1, processes=True))
    with client:
        table = sweep_on(client, scene, vary, shards)
    table.to_csv(sys.stdout, index=False)


if __name__ == "__main__":
    main()
