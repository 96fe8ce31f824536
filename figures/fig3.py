#!/usr/bin/python3
"""Fig. 3: stress along the surface just before the first macroscopic slip, (a) regular
patterns n_p = n_g of growing groove size, (b) unequal pawls and grooves.

We plot the friction force on each block divided by that block's own normal force F_n (see
paper/choices.md): normalising by the total pressure instead would make every pawl block of a
sparser surface look more stressed, which contradicts the paper's reading of panel (b).
The contact profile is the black line under each trace."""
from figures import style


def panel_of(label, entry, pattern):
    if isinstance(entry, dict) and entry.get("panel") in ("a", "b"):
        return entry["panel"]
    kind, _, args = str(pattern).partition(":")
    nums = args.split(",")
    return "a" if kind == "periodic" and len(nums) == 2 and nums[0] == nums[1] else "b"


a = style.arguments(__doc__)
doc = style.load_target(a.data, "fig3")
stress = style.all_stress(doc)
cases = {"a": [], "b": []}
for label, entry, sc in stress:
    sc = sc or {}
    pattern = style.pattern_of(sc) if sc else label
    if style.dig(sc, "x.panel") in ("a", "b"):
        entry = dict(entry, panel=style.dig(sc, "x.panel"))
    cases[panel_of(label, entry, pattern)].append((label, entry, sc))

rows = max(1, len(cases["a"]), len(cases["b"]))
fig, axes = style.plt.subplots(rows, 2, figsize=(7.0, 1.3 + 1.1 * rows), sharey=True, squeeze=False)
for col, key in enumerate(("a", "b")):
    axes[0][col].set_title(f"({key})", loc="left")
    if not cases[key]:
        style.not_produced(axes[0][col], f"fig3{key} stress")
    for row in range(rows):
        ax = axes[row][col]
        if row >= len(cases[key]):
            if row:
                ax.set_visible(False)
            continue
        label, e, sc = cases[key][row]
        f = e.get("f_over_Fn") or []
        contact = e.get("contact") or []
        lx_cm = 100.0 * (style.dig(sc, "result.scene.derived.l_x_m") or 0.0)
        xs = [(i + 0.5) * lx_cm for i in range(len(f))] if lx_cm else list(range(len(f)))
        ax.plot(xs, f, lw=0.8, color=style.COLOURS[row % len(style.COLOURS)])
        if contact:
            # Profile drawn in data units: 1.0 is the threshold of an average block, so the
            # pawls sit at the top and the grooves at zero, under the stress trace.
            edges = [i * (lx_cm or 1) for i in range(len(contact) + 1)]
            ax.stairs([0.05 + 0.1 * c for c in contact], edges, color="black", lw=0.8, baseline=None)
        t = e.get("t_s")
        ax.text(0.99, 0.86, f"{label}" + (f", t = {1e3 * t:.0f} ms" if isinstance(t, (int, float)) else ""),
                transform=ax.transAxes, ha="right", va="top", fontsize=7,
                bbox=dict(fc="white", ec="none", alpha=0.8, pad=1.5))
        if col == 0:
            ax.set_ylabel(r"$|f_i|/F_{n}$")
        if row == len(cases[key]) - 1:
            ax.set_xlabel("L (cm)" if lx_cm else "block index")
# Head room for the case labels; the axes share y, so one call sets them all.
peak = max((max(e.get("f_over_Fn") or [0]) for _, e, _ in stress), default=1.0)
axes[0][0].set_ylim(0, 1.4 * peak if peak > 0 else 1.0)
fig.tight_layout(rect=(0, 0.03, 1, 1))
style.stamp(fig, __file__, doc, "repetition 0; black line: contact profile")
style.save(fig, a.out, "fig3")
