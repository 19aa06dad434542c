"""Sweep of the stand controller's PD bandwidth on the Lola-like biped: one `biped.simulate`
per bandwidth, all in parallel in Rust (`biped.simulate_batch`), and how far the base sinks
and how fast the robot still moves at the end. Plots into out/stand_gain_sweep.png when
matplotlib is installed. Run from the repository root:

    python python/examples/stand_gain_sweep.py
"""
import os

import numpy as np

import biped

bandwidths = np.linspace(10.0, 80.0, 15)
runs = [dict(scenario="stand", duration=2.0, bandwidth=float(w), every=10) for w in bandwidths]
results = biped.simulate_batch(runs)

rows = []
for w, result in zip(bandwidths, results):
    if isinstance(result, biped.BipedError):
        print(f"bandwidth {w:5.1f} rad/s: failed: {result}")
        continue
    summary, signals = result
    sink = signals["q[root.z]"][0] - signals["q[root.z]"].min()
    rows.append((w, 1e3 * sink, summary["final_max_speed"], summary["passed"]))
    print(f"bandwidth {w:5.1f} rad/s: base sinks {1e3 * sink:6.2f} mm, final max speed "
          f"{summary['final_max_speed']:.2e}, checks {'passed' if summary['passed'] else 'FAILED'}")

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("(pip install matplotlib for the plot)")
else:
    w, sink, speed, _ = zip(*rows)
    fig, ax = plt.subplots()
    ax.plot(w, sink, "o-")
    ax.set_xlabel("PD bandwidth [rad/s]")
    ax.set_ylabel("base sinks [mm]")
    ax.set_title("Lola-like biped standing: PD bandwidth sweep")
    os.makedirs("out", exist_ok=True)
    fig.savefig("out/stand_gain_sweep.png", dpi=100)
    print("wrote out/stand_gain_sweep.png")
