"""The time per joint from Python on one scene: `boltzone.solve` called N times (default 200)
after one warm-up call, median and minimum in microseconds; compare with the Rust twin
`cargo run --release -p boltzone-python --example per_joint -- SCENE.toml [N]`.

    python per_joint.py SCENE.toml [N]
"""

import sys
import time

import boltzone


def main():
    path = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 200
    scene = boltzone.Scene.from_toml(path)
    first = boltzone.solve(scene)
    times = []
    for _ in range(n):
        t = time.perf_counter()
        r = boltzone.solve(scene)
        times.append((time.perf_counter() - t) * 1e6)
        assert r.r_o == first.r_o
    times.sort()
    print("python %s: median %.1f us, min %.1f us over %d calls (R_o = %r %s)"
          % (path, times[n // 2], times[0], n, first.r_o, first.length_unit))


if __name__ == "__main__":
    main()
