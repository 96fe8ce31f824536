"""The report's studies beyond the paper: materials given block by block (graded micro friction,
composite soft/hard chains) and the size-scaling study. Every number is read from the study's document; each
study's question and criterion come first, as its driver wrote them before the runs."""
import math
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
# P(|Z| >= 3) for a standard normal Z: the criterion's false-alarm chance per comparison.
TWO_SIDED_3SIGMA = math.erfc(3 / math.sqrt(2))


def provenance_text(doc, path):
    prov = doc["provenance"]
    where = path.relative_to(REPO) if REPO in path.parents else path
    return f"Data: `{where}`, commit {prov['commit']}, {prov['utc']}."


def figure(figs, name):
    png = Path(figs) / f"{name}.png"
    return ("img", str(png) if png.is_file() else None, f"{name}: figures/{name}.py")


def integrator_text(scene):
    """The method a study's scenes ran with, from their scene record."""
    if scene.get("method") == "rk4":
        return f"the paper's fixed-step RK4 at h = {scene['dt_s'] * 1e3:g} ms"
    return (f"the event method ({scene.get('stepper', 'exact')} stepper, tol {scene.get('tol', 0):g}), exact on "
            "chains whose blocks differ")


def cpu_seconds(doc):
    return sum(r.get("cpu_s", 0.0) for s in doc["scenes"] for r in s["result"].get("runs", []))


def stat_text(st):
    return f"{st['mean']:.4f} ± {st['sem']:.4f}" if st.get("mean") is not None else "not measured"


def verdict(c):
    return "resolved" if c["resolved"] else "not resolved"


def diff_text(c):
    return f"{c['diff']:+.4f} ± {c['sem']:.4f}"


def resolved_list(cmp, name):
    hits = [c for c in cmp if c["resolved"]]
    if not hits:
        return "none"
    return "; ".join(f"{name(c)}: {diff_text(c)} (z = {c['z']:+.1f})" for c in hits)


def sign_text(cmp):
    """How many of these differences are resolved, and their signs."""
    hits = [c for c in cmp if c["resolved"]]
    if not hits:
        return f"none of {len(cmp)} resolved"
    neg = sum(c["diff"] < 0 for c in hits)
    sign = "all lower" if neg == len(hits) else "all higher" if neg == 0 else f"{neg} lower, {len(hits) - neg} higher"
    return f"{len(hits)} of {len(cmp)} resolved, {sign} than uniform"


def graded_blocks(doc, path, figs):
    scenes = {s["id"]: s for s in doc["scenes"]}
    cmp = doc["comparisons"]
    reps = cmp[0]["n"]
    label = {s["id"].rsplit("_", 1)[0]: s["x"]["pattern"] for s in doc["scenes"]}
    uniform = [s for s in doc["scenes"] if s["x"]["slope"] == 0]
    B = [("p", f"**Question.** {doc['question']} **Criterion** (fixed before the runs). {doc['criterion']} "
               f"Among its {len(cmp)} comparisons a 3-sigma rule (two-sided chance {TWO_SIDED_3SIGMA:.4f} each "
               f"under no effect) raises one false alarm or more {1 - (1 - TWO_SIDED_3SIGMA) ** len(cmp):.0%} of "
               "the time; a difference not resolved is reported with its standard error, the size of effect the "
               "study could have seen."),
         ("p", "Every block hangs from the slider by its own spring and the slider moves towards +x; block i "
               "rests at i l_x, so the block index grows in the pulling direction (block 0 trails, block N-1 "
               "leads), and 'rising' means micro mu_s growing with the block index. There is no pulled end: "
               "the equations are the same read backwards, so on the smooth surface rising and falling ramps "
               "are the same ensemble and any difference between them is noise; a periodic:10,10 surface laid "
               "out pawl first is not its own mirror image, the only way the direction can enter. "
               f"The paper's chain (N = 360, L_x = 7.2 cm, default parameters), micro mu_s a linear ramp whose "
               f"mean over the contact blocks is {doc['mean_mu_s']:g} (the uniform chain's), total changes "
               f"{', '.join(f'{v:+g}' if v else '0' for v in sorted({s['x']['slope'] for s in doc['scenes']}))}; event method, "
               f"{reps} repetitions of {doc['duration_t0']:g} t0 per scene, one seed for all scenes, so that "
               f"differences are paired repetition by repetition; {cpu_seconds(doc):.1f} CPU s in all "
               f"({doc['wall_seconds']:.1f} s wall). " + provenance_text(doc, path)),
         figure(figs, "graded_friction")]
    B.append(("p", "The uniform chains: " + "; ".join(
        f"{s['x']['pattern']}: mu_s {stat_text(s['result']['mu_s'])}, mu_d {stat_text(s['result']['mu_d'])}"
        for s in uniform) + "."))
    slope = {s["id"].rsplit("_", 1)[1]: s["x"]["slope"] for s in doc["scenes"]}
    rows = [[label[c["surface"]], c["quantity"], c["what"],
             f"{slope[c['a']]:+g}" + (f" vs {slope[c['b']]:+g}" if c["what"] == "rising - falling" else ""),
             diff_text(c), f"{c['z']:+.1f}", verdict(c)] for c in cmp]
    B.append(("table", ["surface", "quantity", "comparison", "mu_s change", "paired difference", "z", "verdict"],
              rows))
    n_res = sum(c["resolved"] for c in cmp)
    worst = max(c["sem"] for c in cmp)
    direction = [c for c in cmp if c["what"] == "rising - falling"]

    def name(c):
        extra = f" vs {slope[c['b']]:+g}" if c["what"] == "rising - falling" else ""
        return f"{label[c['surface']]} {c['quantity']} {slope[c['a']]:+g}{extra}"

    signs = []
    for surface in dict.fromkeys(c["surface"] for c in cmp):
        for key in ("mu_s", "mu_d"):
            g = [c for c in cmp if c["surface"] == surface and c["quantity"] == key and c["what"] == "graded - uniform"]
            signs.append(f"{label[surface]} {key}: {sign_text(g)}")
    B.append(("p", "Graded against uniform, by surface and quantity: " + "; ".join(signs) + "."))
    B.append(("p", f"{n_res} of {len(cmp)} differences are resolved: {resolved_list(cmp, name)}. "
                   f"Direction (rising against falling at the same |change|): "
                   f"{sum(c['resolved'] for c in direction)} of {len(direction)} resolved. "
                   f"The largest standard error of a paired difference is {worst:.4f}: "
                   "effects below about three times that are beyond this study."))
    return B


def composite_blocks(doc, path, figs):
    cmp = doc["comparisons"]
    x_of = {s["id"]: s["x"] for s in doc["scenes"]}
    uniform = next(s for s in doc["scenes"] if s["id"] == "uniform")
    reps = max(c["n"] for c in cmp)
    runs = [r for s in doc["scenes"] for r in s["result"].get("runs", [])]
    per_run = cpu_seconds(doc) / max(1, len(runs))
    B = [("p", f"**Question.** {doc['question']} **Criterion** (fixed before the runs). {doc['criterion']}"),
         ("p", "Segments of L blocks alternate soft and hard from block 0; a hard segment's internal springs and "
               "masses are c times a soft one's, about the uniform chain's (soft 1/sqrt(c), hard sqrt(c)), so "
               "c = 1 is the uniform chain and the local wave speed is the same in both phases "
               "(paper/choices.md, 'Graded and composite chains'). N = 200 over 4 cm (the paper's block size), smooth surface, "
               f"contrasts {', '.join(f'{c:g}' for c in sorted({x['contrast'] for x in x_of.values()} - {1.0}))}, "
               f"segment lengths {', '.join(str(L) for L in sorted({x['segment_blocks'] for i, x in x_of.items() if i != 'uniform'}))} "
               f"blocks; one seed for all scenes (paired). **Integrator**: {integrator_text(uniform['result']['scene'])}; "
               + ("each repetition stops at its first macroscopic slip (mu_s only); "
                  if uniform["result"]["scene"].get("stop_after_mu_s") else "")
               + f"{reps} repetitions of {doc['duration_t0']:g} t0 per scene, {cpu_seconds(doc):.0f} CPU s in all, "
               f"{per_run:.1f} CPU s a repetition ({doc['wall_seconds']:.0f} s wall). " + provenance_text(doc, path)),
         figure(figs, "composite_stiffness"),
         ("p", f"The uniform chain: mu_s {stat_text(uniform['result']['mu_s'])}, "
               f"mu_d {stat_text(uniform['result']['mu_d'])}.")]
    by_id = {}
    for c in cmp:
        by_id.setdefault(c["id"], {})[c["quantity"]] = c
    rows = []
    for i, q in by_id.items():
        row = [f"{x_of[i]['contrast']:g}", str(x_of[i]["segment_blocks"])]
        for key in ("mu_s", "mu_d"):
            c = q.get(key)
            row += [diff_text(c), verdict(c)] if c and c["n"] > 1 else ["not measured", "-"]
        rows.append(row)
    B.append(("table", ["contrast", "segment blocks", "mu_s difference", "mu_s verdict", "mu_d difference",
                        "mu_d verdict"], rows))
    measured = [c for c in cmp if c["n"] > 1]
    for key in ("mu_s", "mu_d"):
        for contrast in sorted({x["contrast"] for i, x in x_of.items() if i != "uniform"}):
            g = sorted([c for c in measured if c["quantity"] == key and x_of[c["id"]]["contrast"] == contrast],
                       key=lambda c: x_of[c["id"]]["segment_blocks"])
            hi = [str(x_of[c["id"]]["segment_blocks"]) for c in g if c["resolved"] and c["diff"] > 0]
            lo = [str(x_of[c["id"]]["segment_blocks"]) for c in g if c["resolved"] and c["diff"] < 0]
            B.append(("p", f"{key}, contrast {contrast:g}: {sign_text(g)}"
                           + (f"; higher with segments of {', '.join(hi)} blocks" if hi else "")
                           + (f"; lower with segments of {', '.join(lo)} blocks" if lo else "") + "."))
    name = lambda c: f"contrast {x_of[c['id']]['contrast']:g}, segments of {x_of[c['id']]['segment_blocks']}, {c['quantity']}"  # noqa: E731
    B.append(("p", f"{sum(c['resolved'] for c in measured)} of {len(measured)} differences are resolved: "
                   f"{resolved_list(measured, name)}. The largest standard error of a paired difference is "
                   f"{max(c['sem'] for c in measured):.4f}."))
    return B


def _fit_text(f, names, digits=4):
    """A fit's parameters with their errors and its chi^2 verdict, or why there is none."""
    if not f.get("converged"):
        return "no fit (" + f.get("reason", "?") + ")"
    pars = ", ".join(f"{n} = {v:.{digits}g} ± {e:.2g}" for n, v, e in zip(names, f["params"], f["errors"]))
    return pars


def _p_text(f):
    if not f.get("converged"):
        return "-"
    return f"{f['chi2']:.1f}/{f['dof']}, p = {f['p']:.2g}"


def _adequate(f):
    return "-" if not f.get("converged") else "adequate" if f["adequate"] else "inadequate"


def _largest_fixed_length(doc, patterns):
    """The patterned surfaces' largest N at fixed L_x, e.g. '10800 (periodic:10,10) and 3600 (...)'."""
    largest = doc["largest_fixed_length"]
    return " and ".join(f"{largest[k]} ({patterns[k]})" for k in largest if patterns.get(k, "smooth") != "smooth")


def _longest_modal_groove(scenes):
    """The longest groove any fixed-L_x scene moved by its modes (modal_max_groove)."""
    return max(s["x"]["modal_max_groove"] for s in scenes if s["x"]["family"] == "fixed_length")


def _last_step(doc, t):
    """A series' change between its last two N, in combined standard errors."""
    from paper import scaling_fits as sf

    pts = sf.points(doc, t["surface"], t["family"], t["quantity"])
    (xa, ya, sa), (xb, yb, sb) = pts[-2], pts[-1]
    d = yb - ya
    return (f"{t['surface']} {t['quantity']} {xa['N']} -> {xb['N']}: {d:+.4f} "
            f"({d / math.hypot(sa, sb):+.1f} combined standard errors)")


def size_scaling_blocks(doc, path, figs):
    """The size-scaling study: question and criterion, scenes and cost, each family's trends, the
    collapse test, the cost per repetition. Fits by paper/scaling_fits.py (the figure's too)."""
    from paper import scaling_fits as sf

    scenes = doc["scenes"]
    runs = [r for s in scenes for r in s["result"].get("runs", [])]
    patterns = {s["x"]["surface"]: s["x"]["pattern"] for s in scenes if s["x"]["N"] == 360}
    reps_by_N = {}
    for s in scenes:
        reps_by_N.setdefault(s["x"]["N"], set()).add(s["result"]["reps"])
    reps_text = ", ".join(f"{'/'.join(str(r) for r in sorted(v))} at {N}" for N, v in sorted(reps_by_N.items()))
    first = scenes[0]["result"]["scene"]
    B = [("p", f"**Question.** {doc['question']} **Criterion** (fixed before the runs, paper/choices.md 'Size "
               f"scaling'). {doc['criterion']} A fit whose chi^2 is inadequate keeps its parameter errors as the "
               "standard errors give them: they then understate the uncertainty."),
         ("p", "The chain's elastic length ell = l_x sqrt(K_int/K_s) = l_z sqrt(E/G) sqrt((N-1)/N) is about "
               f"{scenes[-1]['x']['elastic_length_cm']:.3f} cm whatever N and L_x, because K_int grows as N / L_x "
               "and K_s "
               "falls as L_x / N. At fixed L_x the chain's length in elastic lengths, Lambda = L_x / ell, is fixed and "
               "the blocks per elastic length n_e = ell / l_x grow as N; at fixed l_x it is the other way round; N "
               "itself counts the independent micro thresholds. The load per area and t0 are the same in every "
               "scene. Blocks per groove are proportional to n_e in both families, so they stand or fall with it."),
         ("p", f"Two families through the paper's chain (N = 360, 7.2 cm): fixed L_x = 7.2 cm (finer blocks) and "
               f"fixed l_x = 0.02 cm (longer body); surfaces {', '.join(patterns.values())} as laid out on N = 360, "
               "their physical pawl and groove sizes kept at fixed L_x (block counts scaled with N). "
               f"N from {min(reps_by_N)} to {max(reps_by_N)}; whole runs (mu_s and mu_d) up to N = "
               f"{doc['largest_whole_run']}, larger chains stopped at their first slip (mu_s only), the patterned "
               f"surfaces at fixed L_x only up to N = {_largest_fixed_length(doc, patterns)} (cost: reproduce/"
               f"size_scaling.cpp; their grooves moved by their modes, up to {_longest_modal_groove(scenes)} "
               f"blocks). Repetitions: {reps_text}. **Integrator**: {integrator_text(first)}, "
               f"{doc['duration_t0']:g} t0 per whole run; {cpu_seconds(doc):.0f} CPU s in all over {len(runs)} "
               f"repetitions ({doc['wall_seconds']:.0f} s wall). " + provenance_text(doc, path)),
         figure(figs, "size_scaling")]
    trends = sf.trends(doc)
    rows = []
    for t in trends:
        ll, pl = t["log_linear"], t["power_law"]
        rows.append([t["surface"], t["family"], t["quantity"], f"{t['N_min']}-{t['N_max']}",
                     f"{t['mu_first']:.4f} ± {t['sem_first']:.4f}", f"{t['mu_last']:.4f} ± {t['sem_last']:.4f}",
                     (f"{ll['params'][1]:+.4f} ± {ll['errors'][1]:.4f}" if ll.get("converged") else "-"),
                     _p_text(ll), _adequate(ll), _fit_text(pl, ("a", "b", "c"), 3), _p_text(pl), _adequate(pl)])
    B.append(("p", "Each family's trend against N: the change per decade of N (log-linear fit) and the fit "
                   "mu = a + b N^-c, each with chi^2/dof and its p-value."))
    B.append(("table", ["surface", "family", "quantity", "N", "mu at smallest N", "mu at largest N",
                        "change per decade", "chi^2/dof (log)", "log fit", "a + b N^-c", "chi^2/dof (power)",
                        "power fit"], rows))
    coll = sf.collapses(doc)
    B.append(("p", "The collapse test: one curve mu = a + b X^-c through both families' points of a surface."))
    B.append(("table", ["surface", "quantity", "candidate X", "points", "chi^2/dof", "collapse"],
              [[c["surface"], c["quantity"], c["candidate"], str(c["points"]), _p_text(c["fit"]),
                "yes" if c["collapses"] else "no"] for c in coll]))
    hits = [c for c in coll if c["collapses"]]
    if hits:
        found = "; ".join(f"{c['surface']} {c['quantity']} on {c['candidate']} (p = {c['fit']['p']:.2g})" for c in hits)
        B.append(("p", f"{len(hits)} of {len(coll)} (surface, quantity, candidate) tests collapse: {found}. "
                       "Every other combination fails the criterion."))
    else:
        B.append(("p", f"None of the {len(coll)} (surface, quantity, candidate) tests collapses: no candidate puts "
                       "the two families of any surface on one curve by the criterion."))
    flat = [t for t in trends if t["log_linear"].get("converged") and t["log_linear"]["adequate"]
            and abs(t["log_linear"]["params"][1]) < 3 * t["log_linear"]["errors"][1]]
    B.append(("p", "Series with no resolved trend (an adequate log-linear fit whose change per decade is within 3 "
                   "of its standard errors of zero): " + ("; ".join(f"{t['surface']} {t['family']} {t['quantity']}"
                                                               for t in flat) or "none") + "."))
    B.append(("p", "At fixed L_x the coarsest chains have blocks longer than ell (n_e < 1, K_int < K_s: the paper's "
                   "other regime) and patterns of one-block pawls, so that family mixes the body's size with how "
                   "finely it is discretised. The last step of each of its series (a step of many standard errors says "
                   "its finest chain is not yet the continuum limit): "
                   + "; ".join(_last_step(doc, t) for t in trends if t["family"] == "fixed_length")
                   + "."))
    cost = []
    for s in scenes:
        r = s["result"].get("runs", [])
        if r and s["x"]["N"] >= 3600:
            cost.append([s["x"]["surface"], s["x"]["family"], str(s["x"]["N"]), str(len(r)),
                         "whole" if s["x"]["whole_run"] else "first slip",
                         f"{sum(x['cpu_s'] for x in r) / len(r):.2f}"])
    if cost:
        B.append(("p", "Cost per repetition of the large chains (CPU s, mean over the scene's repetitions):"))
        B.append(("table", ["surface", "family", "N", "repetitions", "run", "CPU s per repetition"], cost))
    return B
