#!/usr/bin/python3
"""Fig. 2: macroscopic mu_d against (mu_d)_m/(mu_s)_m. The K_int = 0 limit (eq. 9 averaged
over the Gaussian draws, provided by the target in `extra`) is the red curve; simulations are
split by coupling (k_int_scale) and damping, the three data sets of the paper."""
from figures import style


def case(s):
    """Data set by its physics, not its name, so the colours follow the paper's whatever the
    driver calls its sets."""
    kis = style.dig(s, "result.scene.k_int_scale", 1.0)
    gamma = style.dig(s, "result.scene.material.gamma_per_s", None)
    if kis == 0:
        # Two K_int = 0 sets: only the undamped one is the setting of eq. (9); damping changes
        # the single-block cycle, so the damped set is kept apart rather than merged.
        return r"$K_{int}=0$, $\gamma=0$" if gamma == 0 else r"$K_{int}=0$, damped"
    return r"coupled, $\gamma=0$" if gamma == 0 else r"coupled, damped"


def ratio(s):
    r = style.dig(s, "x.ratio")
    return r if r is not None else style.dig(s, "x.mu_ratio")


COLOUR = {r"$K_{int}=0$, $\gamma=0$": "#000000", r"$K_{int}=0$, damped": "#999999", r"coupled, damped": "#E69F00", r"coupled, $\gamma=0$": "#0072B2"}

a = style.arguments(__doc__)
doc = style.load_target(a.data, "fig2")
fig, ax = style.plt.subplots(figsize=(4.2, 3.2))
sc = style.scenes(doc)
if not sc:
    style.not_produced(ax, "fig2")
else:
    th = doc.get("theory") or {}
    ex = doc.get("extra") or {}
    curve_x = th.get("ratio") or ex.get("mu_ratio")
    curve_y = th.get("mu_d_M") or ex.get("mu_d_macro")
    if curve_x and curve_y:
        ax.plot(curve_x, curve_y, color="#CC0000", lw=1.2, label="eq. (9), averaged", zorder=1)
    else:
        style.warn("fig2: theory.ratio / theory.mu_d_M missing: no analytic curve")
    for label, items in style.group_by(sc, case).items():
        sets = sorted({str(style.dig(s, "x.set")) for s in items if style.dig(s, "x.set")})
        shown = label + (f" [{', '.join(sets)}]" if sets else "")
        pts = sorted((ratio(s), *style.stat(s, "mu_d")) for s in items if ratio(s) is not None)
        if pts:
            ax.errorbar([p[0] for p in pts], [p[1] for p in pts], yerr=[p[2] for p in pts], fmt="o", ms=3.5,
                        capsize=2, color=COLOUR.get(label), label=shown, zorder=2)
    ax.axvline(0.5, color="k", lw=0.6, ls=":")  # the two regimes of eq. (9) meet at mu_d = mu_s/2
    ax.set_xlabel(r"$(\mu_d)_m/(\mu_s)_m$")
    ax.set_ylabel(r"$(\mu_d)_M$")
    ax.legend()
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc)
style.save(fig, a.out, "fig2")
