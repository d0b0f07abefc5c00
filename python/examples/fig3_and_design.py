"""The screening study's Fig. 3 (contacts and P_max versus θ at four loads, tri-tri and
square-tri, P_crit dashed: `superlube figures`' sweep_*.png) and the design's answer, from Python.
Usage: python fig3_and_design.py [OUT.png]. QUICK=1 (CI): θ in 1° steps, design on four loads
without the DEM and without the fabrication tolerance (the full run: 0.1° steps, the study's
eleven loads, θ ±0.1° × direction ±0.5°, DEM confirmation)."""
import os, sys
import superlube

quick = os.environ.get("QUICK") == "1"
fig3 = {p: superlube.screen(p, theta_deg=f"0:30:{1 if quick else 0.1}", load_mN=[0.35, 1.4, 2.1, 3.86])
        for p in ("tri-tri", "square-tri")}  # fmt: skip
try:
    import matplotlib; matplotlib.use("Agg"); import matplotlib.pyplot as plt  # noqa: E702
    fig, ax = plt.subplots(2, 2, figsize=(11, 6), sharex=True)
    for j, (p, df) in enumerate(fig3.items()):
        for w, g in df.groupby("load_mN"):
            ax[0, j].semilogy(g["theta_deg"], g["contacts"], label=f"{w} mN")
            ax[1, j].plot(g["theta_deg"], g["p_max_GPa"])
        ax[1, j].axhline(4.0, ls="--", c="k"), ax[0, j].set_title(p), ax[1, j].set_xlabel("θ (degrees)")
    ax[0, 0].set_ylabel("contacts"), ax[1, 0].set_ylabel("P_max (GPa)"), ax[0, 0].legend()
    fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "fig3.png", dpi=120)
except ImportError:
    print("matplotlib is not installed: no figure")
kw = dict(load_mN="0.35,1.4,2.45,3.5", no_dem=True, theta_tol_deg=0, direction_tol_deg=0) if quick else {}
ranking, summary = superlube.design(pattern="tri-tri,square-tri", **kw)
for p, answer in summary["answer"].items():
    print(f"design answer, {p}: {answer}")
