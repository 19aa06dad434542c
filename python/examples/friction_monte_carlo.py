"""Monte-Carlo robustness of the dynamic walk against the ground's friction: the walk of
`biped walk --dynamic` on grounds whose Coulomb coefficient is drawn at random, all of them
in parallel (`biped.walk_batch`; `biped.distributed.sweep(runs, command="walk")` runs the
same list on a Ray cluster), and how many walk, slip or fall. Run from the repository root:

    python python/examples/friction_monte_carlo.py [SAMPLES]
"""
import sys

import numpy as np

import biped

samples = int(sys.argv[1]) if len(sys.argv) > 1 else 8
rng = np.random.default_rng(1)
mus = rng.uniform(0.15, 1.0, samples)
runs = [dict(steps=4, method="none", dynamic=True, friction=float(mu), allow_violations=True) for mu in mus]


def verdict(result):
    if isinstance(result, biped.BipedError):  # a fall is the walk's error
        return "fell", str(result)
    d = result[0]["dynamic"]
    return ("slipped" if d["slip_at"] is not None else "walked"), f"{d['max_slip_distance'] * 1e3:.1f} mm slip"


outcomes = sorted((mu, *verdict(r)) for mu, r in zip(mus, biped.walk_batch(runs)))
for mu, verdict, detail in outcomes:
    print(f"mu = {mu:.2f}: {verdict} ({detail})")
counts = {v: sum(o[1] == v for o in outcomes) for v in ("walked", "slipped", "fell")}
print(", ".join(f"{n} {v}" for v, n in counts.items()), f"of {samples}")
