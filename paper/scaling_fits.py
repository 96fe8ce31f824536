"""Fits of the size-scaling study (reproduce/size_scaling.cpp), shared by its figure and the report.

Each family's trend of mu against N is fitted by weighted least squares on the repetitions'
standard errors (scipy curve_fit with absolute_sigma, so the covariance is the errors', not
rescaled by the fit's scatter), in two forms: mu = a + b log10 N and mu = a + b N^-c. A fit is
adequate when its chi^2 p-value is at least ADEQUATE_P (paper/choices.md, "Size scaling"; fixed
before the study ran). A candidate variable X collapses a surface's two families when one
mu = a + b X^-c through both families' points is adequate by the same rule.

The candidates use the chain's elastic length at large N, ell = l_z sqrt(E/G): the recorded
elastic_length_cm times sqrt(N/(N-1)). That makes Lambda = L_x / ell exactly constant at a fixed
L_x (and n_e = ell / l_x exactly constant at a fixed l_x) instead of drifting by the 1.4% that
(N-1)/N moves at N = 36, which would let a steep curve thread a family through a sliver of X.
The number of blocks per groove is proportional to n_e in both families (the pattern's physical
sizes are fixed), so it collapses exactly when n_e does and is not tried apart."""
import math

import numpy as np
from scipy import optimize, stats

ADEQUATE_P = 0.01
FAMILIES = ("fixed_length", "fixed_block")
QUANTITIES = ("mu_s", "mu_d")
CANDIDATES = ("N", "Lambda", "n_e")


def candidate(x, name):
    """The value of candidate `name` for a scene's plot coordinates `x` (the driver's x block)."""
    N = x["N"]
    if name == "N":
        return float(N)
    ell = x["elastic_length_cm"] * math.sqrt(N / (N - 1))
    return x["L_x_cm"] / ell if name == "Lambda" else ell / x["l_x_cm"]


def points(doc, surface, family, key):
    """[(x, mean, sem)] of one series, in N order; points without a standard error (fewer than two
    repetitions measured it) cannot be weighted and are left out."""
    out = []
    for s in doc["scenes"]:
        x, st = s["x"], s["result"].get(key) or {}
        if x["surface"] == surface and x["family"] == family and st.get("n", 0) >= 2 and st.get("sem", 0) > 0:
            out.append((x, st["mean"], st["sem"]))
    return sorted(out, key=lambda p: p[0]["N"])


def surfaces(doc):
    return list(dict.fromkeys(s["x"]["surface"] for s in doc["scenes"]))


def _fit(model, x, y, sem, p0, bounds=(-np.inf, np.inf)):
    x, y, sem = (np.asarray(v, float) for v in (x, y, sem))
    dof = len(x) - len(p0)
    if dof < 1:
        return {"converged": False, "reason": f"{len(x)} points for {len(p0)} parameters"}
    try:
        par, cov = optimize.curve_fit(model, x, y, p0=p0, sigma=sem, absolute_sigma=True, bounds=bounds,
                                      maxfev=20000)
    except (RuntimeError, ValueError, optimize.OptimizeWarning) as e:
        return {"converged": False, "reason": str(e).split("\n")[0]}
    err = np.sqrt(np.clip(np.diag(cov), 0, np.inf))
    if not np.all(np.isfinite(err)):
        return {"converged": False, "reason": "singular covariance"}
    chi2 = float(np.sum(((y - model(x, *par)) / sem) ** 2))
    p = float(stats.chi2.sf(chi2, dof))
    return {"converged": True, "params": [float(v) for v in par], "errors": [float(v) for v in err],
            "chi2": chi2, "dof": dof, "p": p, "adequate": p >= ADEQUATE_P}


def log_linear(x, y, sem):
    """mu = a + b log10 x: params [a, b] (b is the change per decade)."""
    return _fit(lambda t, a, b: a + b * np.log10(t), x, y, sem, [float(np.mean(y)), 0.0])


def power_law(x, y, sem):
    """mu = a + b x^-c, c in [1e-3, 5]: params [a, b, c]. Started from the largest x's value and a
    square-root approach (the fibre bundle's), the usual answer for a weakest-link strength."""
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    i0, i1 = int(np.argmin(x)), int(np.argmax(x))
    c0 = 0.5
    b0 = (y[i0] - y[i1]) / max(x[i0] ** -c0 - x[i1] ** -c0, 1e-12)
    return _fit(lambda t, a, b, c: a + b * np.power(t, -c), x, y, sem, [float(y[i1]), float(b0), c0],
                bounds=([-np.inf, -np.inf, 1e-3], [np.inf, np.inf, 5.0]))


def trends(doc):
    """Per surface, family and quantity: the points' N range, both fits."""
    out = []
    for surface in surfaces(doc):
        for family in FAMILIES:
            for key in QUANTITIES:
                pts = points(doc, surface, family, key)
                if not pts:
                    continue
                N = [p[0]["N"] for p in pts]
                y = [p[1] for p in pts]
                sem = [p[2] for p in pts]
                out.append({"surface": surface, "family": family, "quantity": key, "points": len(pts),
                            "N_min": min(N), "N_max": max(N), "mu_first": y[0], "sem_first": sem[0],
                            "mu_last": y[-1], "sem_last": sem[-1],
                            "log_linear": log_linear(N, y, sem), "power_law": power_law(N, y, sem)})
    return out


def collapses(doc):
    """Per surface, quantity and candidate: one power law in the candidate through both families."""
    out = []
    for surface in surfaces(doc):
        for key in QUANTITIES:
            pts = [p for family in FAMILIES for p in points(doc, surface, family, key)]
            if not pts:
                continue
            for name in CANDIDATES:
                X = [candidate(p[0], name) for p in pts]
                fit = power_law(X, [p[1] for p in pts], [p[2] for p in pts])
                out.append({"surface": surface, "quantity": key, "candidate": name, "points": len(pts), "fit": fit,
                            "collapses": bool(fit.get("converged") and fit["adequate"])})
    return out
