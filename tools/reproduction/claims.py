"""Figure claims (tables/figure_claims.tsv): one small function per claim, registered with the
reproduction targets it reads. Adding a claim is one function here and one line in the TSV.

Each function receives a lines.Claim to fill, the claim's parameters (key=value of the TSV) and
a View of the results that lets it read only the targets it is registered for, so the registry
(and with it the CTest fixtures each claim requires) cannot drift from what the code reads.
Margins and thresholds are the rules of lines.py; nothing here picks a tolerance of its own
except what the claim's own parameters state (max=, tol=, value=)."""
import math
import statistics

from . import stats
from .inputs import statistic, table_target

REGISTRY = {}   # claim_id -> (function, targets: tuple of names or callable(params) -> names)


def claim(*ids, targets):
    def register(fn):
        for cid in ids:
            if cid in REGISTRY:
                raise ValueError(f"claim {cid} registered twice")
            REGISTRY[cid] = (fn, targets)
        return fn
    return register


def rows_in(*keys):
    """Targets of a claim about table rows: the tables of the row ids named in these parameters."""
    def targets(params):
        ids = [tok for k in keys for tok in _row_tokens(params[k])]
        return tuple(sorted({table_target(r) for r in ids}))
    return targets


def targets_of(cid, params):
    t = REGISTRY[cid][1]
    return tuple(t(params)) if callable(t) else tuple(t)


def parse_params(text):
    out = {}
    for piece in text.split(";"):
        if "=" in piece:
            k, v = piece.split("=", 1)
            out[k.strip()] = v.strip()
    return out


def _row_tokens(text):
    """Every row id in a parameter value, whatever the separators (, > < | : ..)."""
    for sep in (">", "<", "|", ":", ".."):
        text = text.replace(sep, ",")
    return [t for t in text.split(",") if "_r" in t]


def expand(ids):
    """'pat1_r04..pat1_r09' -> the ids in between."""
    out = []
    for item in ids.split(","):
        if ".." in item:
            a, b = item.split("..")
            pre = a.rsplit("_r", 1)[0]
            out += [f"{pre}_r{i:02d}" for i in range(int(a.rsplit("_r", 1)[1]), int(b.rsplit("_r", 1)[1]) + 1)]
        elif item:
            out.append(item)
    return out


def coef_of(params):
    return "mu_d" if params["observable"].startswith("mu_d") else "mu_s"


class View:
    """The results a claim may read: only its registered targets (and the published tables)."""

    def __init__(self, res, pub, cid, targets):
        self.res, self.pub, self.cid, self.targets = res, pub, cid, set(targets)

    def doc(self, target):
        if target not in self.targets:
            raise RuntimeError(f"claim {self.cid} reads {target}, which it is not registered for")
        return self.res.need(target)

    def scene(self, target, sid):
        self.doc(target)
        return self.res.scene(target, sid)

    def stat(self, target, sid, coef):
        """(mean, sem) of one scene."""
        m, s, _, _ = statistic(self.scene(target, sid), coef)
        return m, s

    def row(self, rid, coef="mu_s"):
        return self.stat(table_target(rid), rid, coef)

    def sweep(self, target, key, value, coef, xkey):
        """[(x, (mean, sem))] of the scenes with x[key] == value, by x. Points without a value
        (no macroscopic slip) are not part of a curve."""
        pts = [(s["x"][xkey], self.stat(target, s["id"], coef)) for s in self.doc(target)["scenes"]
               if s["x"][key] == value and s["result"][coef]["mean"] is not None]
        return sorted(pts, key=lambda p: p[0])


def pooled_mean(values):
    """Mean of (mean, sem) values and its standard error (independent values)."""
    return (statistics.fmean(v[0] for v in values), math.sqrt(sum(v[1] ** 2 for v in values)) / len(values))


def ordered_pairs(c, v, pairs, coef):
    """pairs 'A>B,C<D': each as an ordering of the two rows' coefficient."""
    for p in pairs.split(","):
        if ">" in p:
            a, b = p.split(">")
            c.ordered(v.row(a, coef), v.row(b, coef), f"{a} > {b}", coef)
        else:
            a, b = p.split("<")
            c.ordered(v.row(b, coef), v.row(a, coef), f"{a} < {b}", coef)


def ordered_chains(c, v, chains, coef):
    """Non-strict decrease along each chain of row ids."""
    for ch in chains:
        for hi, lo in zip(ch, ch[1:]):
            c.ordered(v.row(hi, coef), v.row(lo, coef), f"{hi} >= {lo}", coef)


# ---------------------------------------------------------------- fig_s1, fig_s2, fig1
@claim("C01", targets=("fig_s1",))
def mu_d_flat_over_N(c, p, v):
    for st in ("default", "narrow"):
        c.spread(f"{st} set: mu_d over N", [(f"N={n}", m) for n, m in v.sweep("fig_s1", "set", st, "mu_d", "N")],
                 float(p["max"]))


@claim("C02", targets=("fig_s1",))
def mu_s_falls_with_N(c, p, v):
    for st in ("default", "narrow"):
        pts = v.sweep("fig_s1", "set", st, "mu_s", "N")
        for (n1, a), (n2, b) in zip(pts, pts[1:]):
            c.ordered(a, b, f"{st}: mu_s(N={n1}) >= mu_s(N={n2})", "mu_s")


@claim("C03", targets=("fig_s1",))
def narrow_spread_higher_mu_s(c, p, v):
    d = dict(v.sweep("fig_s1", "set", "default", "mu_s", "N"))
    n = dict(v.sweep("fig_s1", "set", "narrow", "mu_s", "N"))
    for N in sorted(set(d) & set(n)):
        c.ordered(n[N], d[N], f"N={N}: narrow > default", "mu_s")


@claim("C04", targets=rows_in("rows"))
def smooth_mu_d_above_micro(c, p, v):
    micro = float(p["mu_d_m"])
    c.ordered(v.row(p["rows"], "mu_d"), (micro, 0.0), f"smooth mu_d > (mu_d)_m = {micro}", "mu_d")


def fig_s2_curves(v, coef):
    """{N: [(K_int/K_s, (mean, sem))]} of fig_s2."""
    Ns = sorted({s["x"]["N"] for s in v.doc("fig_s2")["scenes"]})
    return {N: v.sweep("fig_s2", "N", N, coef, "K_int_over_K_s") for N in Ns}


def plateau(curve):
    """The K_int > K_s part of a curve, pooled."""
    return pooled_mean([m for x, m in curve if x > 1])


@claim("C05", targets=("fig_s2",))
def mu_s_flat_for_stiff_chains(c, p, v):
    for N, curve in fig_s2_curves(v, "mu_s").items():
        c.spread(f"N={N}: mu_s for K_int/K_s > 1", [(f"{x:.3g}", m) for x, m in curve if x > 1], float(p["tol"]))


@claim("C06", targets=("fig_s2",))
def mu_s_rises_for_soft_chains(c, p, v):
    for N, curve in fig_s2_curves(v, "mu_s").items():
        x0, low = curve[0]
        c.ordered(low, plateau(curve), f"N={N}: mu_s at K_int/K_s={x0:.3g} above the K_int > K_s plateau", "mu_s")


@claim("C07", targets=("fig_s2",))
def mu_d_rises_for_soft_chains(c, p, v):
    for N, curve in fig_s2_curves(v, "mu_d").items():
        for (x1, a), (x2, b) in zip(curve, curve[1:]):
            c.ordered(a, b, f"N={N}: mu_d({x1:.3g}) >= mu_d({x2:.3g})", "mu_d")


@claim("C08", targets=("fig_s2",))
def plateau_falls_with_N(c, p, v):
    plateaus = [(N, plateau(curve)) for N, curve in fig_s2_curves(v, "mu_s").items()]
    for (n1, a), (n2, b) in zip(plateaus, plateaus[1:]):
        c.ordered(a, b, f"plateau mu_s N={n1} > N={n2}", "mu_s")


@claim("C09", targets=("fig1",))
def peak_above_sliding_mean(c, p, v):
    # Both are friction over load; the static margin (0.03) is the relevant scale of a peak.
    c.ordered(v.stat("fig1", "smooth_N200", "mu_s"), v.stat("fig1", "smooth_N200", "mu_d"),
              "first peak (mu_s) > sliding mean (mu_d)", "mu_s")


# ---------------------------------------------------------------- fig2: eq. 9
def eq9(v):
    """Eq. (9) averaged over the micro coefficients, at the tabulated ratio nearest to r."""
    th = v.doc("fig2")["theory"]
    return lambda r: min(zip(th["ratio"], th["mu_d_M"]), key=lambda q: abs(q[0] - r))[1]


@claim("C10", targets=("fig2",))
def independent_blocks_follow_eq9(c, p, v):
    theory, tol = eq9(v), float(p["tol"])
    for r, (m, s) in v.sweep("fig2", "set", "kint0", "mu_d", "ratio"):
        c.at_most(f"r={r:g}: K_int=0 |mu_d - eq.9| ({m:.4f} vs {theory(r):.4f})", abs(m - theory(r)), s, tol,
                  sides=2)


@claim("C11", targets=("fig2",))
def chains_depart_from_eq9_below_half(c, p, v):
    theory, tol = eq9(v), float(p["tol"])
    for st in ("damped", "undamped"):
        pts = v.sweep("fig2", "set", st, "mu_d", "ratio")
        for r, (m, s) in pts:
            if r >= 0.5:
                c.at_most(f"{st} r={r:g}: |mu_d - eq.9| ({m:.4f} vs {theory(r):.4f})", abs(m - theory(r)), s, tol,
                          sides=2)
        below = [(f"r={r:g}", abs(m - theory(r)), s) for r, (m, s) in pts if r < 0.5]
        c.any_beyond(f"{st}: departs from eq.9 somewhere below r = 0.5", below, tol)


@claim("C12", targets=("fig2",))
def independent_blocks_not_below_micro(c, p, v):
    th = v.doc("fig2")["theory"]
    for r, (m, s) in v.sweep("fig2", "set", "kint0", "mu_d", "ratio"):
        # A block's micro mu_d is clipped to its mu_s (the simulator's draw policy), so the micro
        # mean is E[min(mu_d, mu_s)] = r - E[(r - mu_s)+] with mu_s ~ N(mu_s_m, sigma_s).
        zz = (r - th["mu_s_m"]) / th["sigma_s"]
        micro = r - th["sigma_s"] * (zz * stats.normal_cdf(zz) + stats.normal_pdf(zz))
        c.ordered((m, s), (micro, 0.0), f"r={r:g}: K_int=0 mu_d >= micro mean {micro:.4f}", "mu_d")


# ---------------------------------------------------------------- fig_p1, fig3
@claim("C13", targets=("fig_p1",))
def critical_groove_density(c, p, v):
    cr, value, tol = v.doc("fig_p1")["critical"]["N_g_over_N_cr"], float(p["value"]), float(p["tol"])
    c.exact(f"(N_g/N)_cr = {cr:.4f} vs {value} +- {tol}", abs(cr - value) <= tol)


@claim("C14", targets=rows_in("rows", "ref"))
def no_reduction_small_grooves(c, p, v):
    for r in p["rows"].split(","):
        c.ordered(v.row(r), v.row(p["ref"]), f"{r} not below {p['ref']}", "mu_s")


@claim("C15", "C20", "C21", "C25", "C26", "C29", "C31", targets=rows_in("pairs"))
def row_pairs(c, p, v):
    ordered_pairs(c, v, p["pairs"], coef_of(p))


@claim("C16", targets=rows_in("rows"))
def mu_s_falls_with_groove_at_half(c, p, v):
    ordered_chains(c, v, [p["rows"].split(",")], "mu_s")


@claim("C17", targets=rows_in("rows"))
def mu_d_flat_at_half(c, p, v):
    rows = expand(p["rows"])
    c.spread("mu_d at S = 1/2", [(r, v.row(r, "mu_d")) for r in rows], float(p["max"]))


def edge_stress(scene, field, index):
    """Mean |stress| over the contact blocks next to a groove, in snapshot `index`."""
    mask, vals = scene["contact_mask"], scene["stress"][index][field]
    edge = [i for i in range(len(mask)) if mask[i] == "1" and
            ((i > 0 and mask[i - 1] == "0") or (i + 1 < len(mask) and mask[i + 1] == "0"))]
    return statistics.fmean(abs(vals[i]) for i in edge)


def fig3_edges(v, ids, field):
    doc = v.doc("fig3")
    scenes = {s["id"]: s for s in doc["scenes"]}
    return [edge_stress(scenes[i], field, doc["snapshot"]["index"]) for i in ids]


@claim("C18", targets=("fig3",))
def edge_stress_grows_with_groove(c, p, v):
    # One snapshot of repetition 0: a deterministic comparison, no standard error.
    s = fig3_edges(v, ["a_periodic_4_4", "a_periodic_10_10", "a_periodic_30_30"], "sigma_over_P")
    c.exact("edge sigma/P rises with n_g = 4, 10, 30: " + ", ".join(f"{x:.3f}" for x in s), s[0] < s[1] < s[2])


@claim("C19", targets=("fig3",))
def small_pawls_lower_edge_stress(c, p, v):
    a, b = fig3_edges(v, ["b_periodic_10_30", "a_periodic_30_30"], "f_over_Fn")
    c.exact(f"edge f/F_n: n_p=10,n_g=30 {a:.3f} < n_p=n_g=30 {b:.3f}", a < b)


# ---------------------------------------------------------------- tables
@claim("C22", targets=rows_in("groups"))
def mu_s_falls_with_groove_at_fixed_S(c, p, v):
    ordered_chains(c, v, [g.split(":")[1].split(",") for g in p["groups"].split("|")], "mu_s")


@claim("C23", targets=("tab_pat0",))
def mu_d_rises_as_contact_falls(c, p, v):
    groups = {}
    for rid, r in v.pub.items():
        if table_target(rid) == "tab_pat0":
            S = int(r["S_over_Stot_num"]) / int(r["S_over_Stot_den"])
            groups.setdefault(S, []).append(v.row(rid, "mu_d"))
    means = [(S, pooled_mean(g)) for S, g in sorted(groups.items(), reverse=True)]
    for (s1, a), (s2, b) in zip(means, means[1:]):
        c.ordered(b, a, f"mean mu_d at S={s2:.3f} >= at S={s1:.3f}", "mu_d")


@claim("C24", targets=("fig_p1",))
def random_grooves_weakest(c, p, v):
    rnd = v.stat("fig_p1", "random_0.5", "mu_s")
    c.ordered((float(p["value"]), 0.0), rnd, f"random below {p['value']} (smallest printed single-level)", "mu_s")
    for s in v.doc("fig_p1")["scenes"]:
        if s["id"].startswith("periodic_"):
            c.ordered(v.stat("fig_p1", s["id"], "mu_s"), rnd, f"random below {s['id']}", "mu_s")


@claim("C27", targets=rows_in("chain"))
def progressive_reduction(c, p, v):
    ordered_chains(c, v, [ch.split(">") for ch in p["chain"].split("|")], "mu_s")


@claim("C28", targets=rows_in("min_of"))
def parent_lowest_of_family(c, p, v):
    for fam in p["min_of"].split("|"):
        parent, members = fam.split(":")
        for m in expand(members):
            if m != parent:
                c.ordered(v.row(m), v.row(parent), f"{parent} <= {m}", "mu_s")


@claim("C30", targets=rows_in("set_a", "set_b"))
def hierarchical_minimum_lowest(c, p, v):
    a = min((v.row(r) for r in p["set_a"].split(",")), key=lambda m: m[0])
    b = min((v.row(r) for r in p["set_b"].split(",")), key=lambda m: m[0])
    c.ordered(b, a, "min over hierarchical S=1/4 < min over single-level S=1/4", "mu_s")


@claim("C32", targets=rows_in("rows", "ref"))
def hierarchical_mu_d_near_smooth(c, p, v):
    ref = v.row(p["ref"], "mu_d")
    pairs = [(r, v.row(r, "mu_d"), p["ref"], ref) for r in expand(p["rows"])]
    c.all_close(f"|mu_d - mu_d({p['ref']})| / mu_d({p['ref']})", pairs, float(p["max"]), ref[0])


# ---------------------------------------------------------------- fig5
@claim("C33", targets=("fig5",))
def smooth_peak_above_one_level(c, p, v):
    c.ordered(v.stat("fig5", "smooth", "mu_s"), v.stat("fig5", "one_level", "mu_s"), "smooth peak > one-level",
              "mu_s")


@claim("C34", targets=("fig5",))
def two_level_peak_above_one_level(c, p, v):
    c.ordered(v.stat("fig5", "two_level", "mu_s"), v.stat("fig5", "one_level", "mu_s"),
              "two-level peak > one-level", "mu_s")


def sliding_std(scene):
    """Standard deviation of mu(t) over the mu_d window of repetition 0's trace."""
    sc, t_slip = scene["result"]["scene"], scene["result"]["runs"][0]["t_slip_s"]
    if t_slip is None:
        raise LookupError(f"{scene['id']}: repetition 0 never slipped, no sliding phase")
    start = t_slip + sc["mu_d_skip_t0"] * sc["t0_s"]
    vals = [m for t, m in zip(scene["series"]["t_s"], scene["series"]["mu"]) if t >= start and m is not None]
    return statistics.pstdev(vals)


@claim("C35", targets=("fig5",))
def same_sliding_mean_more_fluctuation(c, p, v):
    c.spread("dynamic means of smooth, one-level, two-level",
             [(s, v.stat("fig5", s, "mu_d")) for s in ("smooth", "one_level", "two_level")],
             float(p["mean_rel_tol"]))
    # One trace (repetition 0) per surface: a deterministic comparison of that trace.
    one, two = (sliding_std(v.scene("fig5", s)) for s in ("one_level", "two_level"))
    c.exact(f"sliding-phase std of repetition 0: two-level {two:.4f} > one-level {one:.4f}", two > one)
