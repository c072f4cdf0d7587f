"""Fit synergies from a numpy array of hand postures and plot the variance they cover.

The postures here are made up (a few latent motions mixed into the 13 SAH joints, with noise); use
your own (frames, joints) array of mapped glove postures in radians. The plot (the paper's Fig. 10)
needs matplotlib (Debian: python3-matplotlib); without it the table is printed only.

    PYTHONPATH=build/python python3 examples/python/fit_synergies.py [OUT.png]
"""
import sys

import numpy as np

import pmdplan

robot = pmdplan.Robot.builtin("sah_tx90")
hand = robot.groups["hand"]
lower, upper = robot.lower[hand], robot.upper[hand]
rng = np.random.default_rng(1)
latent = rng.standard_normal((5000, 3)) * [0.2, 0.08, 0.03]
mixing = rng.standard_normal((3, len(hand)))
unit = np.clip(0.5 + latent @ mixing / np.sqrt(3) + 0.005 * rng.standard_normal((5000, len(hand))), 0, 1)
postures = lower + unit * (upper - lower)

fit = pmdplan.fit_synergies(postures, robot, own_axis_joints=["thumb_base"], provenance="fit_synergies.py example")
model = fit["model"]
print(f"{fit['frames']} frames; PCA over {len(fit['pca_joints'])} joints")
for k, share in enumerate(fit["cumulative_variance"][:6], start=1):
    print(f"  first {k} PMDs: {100 * share:5.1f} % of the variance")
model.save("fitted_synergies.yaml")
print("model written to fitted_synergies.yaml (plan with it: pmdplan plan --synergies fitted_synergies.yaml)")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
out = sys.argv[1] if len(sys.argv) > 1 else "cumulative_variance.png"
counts = np.arange(1, len(model.cumulative_variance) + 1)
plt.figure(figsize=(5, 3.5))
plt.plot(counts, 100 * model.cumulative_variance, "o-")
plt.xlabel("principal motion directions")
plt.ylabel("cumulative variance (%)")
plt.ylim(0, 101)
plt.grid(alpha=0.3)
plt.tight_layout()
plt.savefig(out, dpi=120)
print(f"plot written to {out}")
