#!/usr/bin/python3
"""Times one start of a perceptual-space fit in numpy + scipy's L-BFGS-B, the reference for
bench_space.cpp's BM_SpaceStartLagunas3D: the same judgment models (model/space/judgment_model.hpp),
the same data (Lagunas et al. 2019's training split, 3-D), starts drawn the same way (normal, sd 1,
stimulus 0 pinned at the origin).

Run with Debian's interpreter, which has numpy and scipy:  /usr/bin/python3 tests/bench/numpy_space_fit.py
Prints, per model, seconds per start (median of 3 starts), the best objective reached and the mean
evaluations a start, beside which the C++ benchmark's `objective` and `evaluations` counters tell that
both reach the same optima with about as many evaluations.
The objective is written vectorised over triplets with an analytic gradient (np.bincount to gather
it per stimulus), as a numpy user would; the gradient is checked against finite differences first.
"""
import json
import math
import os
import statistics
import sys
import time

import numpy as np
from scipy import optimize, special

SCALE = 2.0 / 3.0
LOGISTIC_SLOPE = 1.702
NOISE_PRIOR_SD = 0.5
STUDENT_COORDINATE_PRIOR_SD = 10.0  # kStudentCoordinatePriorSd


def lagunas(path):
    with open(path) as f:
        data = json.load(f)
    answers = np.array(data["answers"], dtype=np.int64)
    counts = np.array(data["agreement"], dtype=np.float64)
    return answers[:, 0], answers[:, 1], answers[:, 2], counts[:, 0], counts[:, 1], int(answers.max()) + 1


def softplus(x):
    return np.logaddexp(0.0, x)


def link_terms(link, alpha, xa, xb):
    """log P(a), log P(b) and their derivatives in x_a and x_b."""
    if link == "probit":
        z = xb - xa
        la, lb = special.log_ndtr(z), special.log_ndtr(-z)
        ra = np.exp(-0.5 * z * z - 0.5 * math.log(2 * math.pi) - la)
        rb = np.exp(-0.5 * z * z - 0.5 * math.log(2 * math.pi) - lb)
        return la, lb, -ra, ra, rb, -rb
    if link == "logistic":
        cz = LOGISTIC_SLOPE * (xb - xa)
        la, lb = -softplus(-cz), -softplus(cz)
        ga, gb = LOGISTIC_SLOPE * special.expit(-cz), LOGISTIC_SLOPE * special.expit(cz)
        return la, lb, -ga, ga, gb, -gb
    # Student-t kernels: P(a) = 1 / (1 + e^u), u = log K(x_b) − log K(x_a)
    log_k = lambda x: -0.5 * (alpha + 1.0) * np.log1p(x * x / alpha)
    log_k_dx = lambda x: -(alpha + 1.0) * x / (alpha + x * x)
    u = log_k(xb) - log_k(xa)
    la, lb = -softplus(u), -softplus(-u)
    du_dxa, du_dxb = -log_k_dx(xa), log_k_dx(xb)
    la_du, lb_du = -special.expit(u), special.expit(-u)
    return la, lb, la_du * du_dxa, la_du * du_dxb, lb_du * du_dxa, lb_du * du_dxb


def make_objective(family, data, dims):
    r, a, b, ca, cb, n = data
    link = family.split("+")[0]
    lapse_on, noise_on = "+lapse" in family, "+noise" in family
    alpha = max(1.0, dims - 1.0)
    free = dims * (n - 1)

    def f(x):
        q = np.zeros((dims, n))
        q[:, 1:] = x[:free].reshape(n - 1, dims).T
        k = free
        eps = 0.0
        if lapse_on:
            eps = 0.5 * special.expit(x[k])
            k += 1
        eta = x[k:k + n] if noise_on else None
        va, vb = q[:, a] - q[:, r], q[:, b] - q[:, r]
        da, db = np.sqrt((va * va).sum(0)), np.sqrt((vb * vb).sum(0))
        if noise_on:
            s2 = np.exp(2 * eta)
            var = (s2[r] + s2[a] + s2[b]) / 3.0
            log_sigma = 0.5 * np.log(var)
        else:
            log_sigma = 0.0
        per = SCALE * np.exp(-log_sigma)
        xa, xb = per * da, per * db
        la, lb, la_a, la_b, lb_a, lb_b = link_terms(link, alpha, xa, xb)
        if lapse_on:
            guess = math.log(0.5 * eps)
            pa, pb = np.logaddexp(guess, math.log1p(-eps) + la), np.logaddexp(guess, math.log1p(-eps) + lb)
            wa, wb = np.exp(math.log1p(-eps) + la - pa), np.exp(math.log1p(-eps) + lb - pb)
            d_eps = -(ca * (0.5 - np.exp(la)) * np.exp(-pa) + cb * (0.5 - np.exp(lb)) * np.exp(-pb)).sum()
        else:
            pa, pb, wa, wb = la, lb, 1.0, 1.0
        value = -(ca * pa + cb * pb).sum()
        dxa = -(ca * wa * la_a + cb * wb * lb_a)
        dxb = -(ca * wa * la_b + cb * wb * lb_b)
        g_da, g_db = dxa * per, dxb * per
        ka = np.where(da > 0, g_da / np.where(da > 0, da, 1.0), 0.0)
        kb = np.where(db > 0, g_db / np.where(db > 0, db, 1.0), 0.0)
        grad_q = np.empty((dims, n))
        for d in range(dims):
            wa_d, wb_d = ka * va[d], kb * vb[d]
            grad_q[d] = (np.bincount(a, wa_d, n) + np.bincount(b, wb_d, n) - np.bincount(r, wa_d + wb_d, n))
        grad = [grad_q[:, 1:].T.reshape(-1)]
        if link == "student-t":
            value += 0.5 * (x[:free] ** 2).sum() / STUDENT_COORDINATE_PRIOR_SD ** 2
            grad[0] = grad[0] + x[:free] / STUDENT_COORDINATE_PRIOR_SD ** 2
        if lapse_on:
            u = special.expit(x[free])
            grad.append(np.array([d_eps * 0.5 * u * (1 - u)]))
        if noise_on:
            g_ls = -(dxa * xa + dxb * xb)
            w = g_ls / (3.0 * var)
            g_eta = (np.bincount(r, w * s2[r], n) + np.bincount(a, w * s2[a], n) + np.bincount(b, w * s2[b], n))
            value += 0.5 * (eta * eta).sum() / NOISE_PRIOR_SD ** 2
            grad.append(g_eta + eta / NOISE_PRIOR_SD ** 2)
        return value, np.concatenate(grad)

    size = free + (1 if lapse_on else 0) + (n if noise_on else 0)
    return f, size, free, lapse_on


def start(size, free, lapse_on, seed):
    rng = np.random.default_rng(seed)
    x = np.zeros(size)
    x[:free] = rng.normal(0.0, 1.0, free)
    if lapse_on:
        x[free] = math.log(2 * 0.02 / (1 - 2 * 0.02))
    return x


def check_gradient(f, x):
    value, grad = f(x)
    rng = np.random.default_rng(3)
    for i in rng.choice(x.size, 5, replace=False):
        h = 1e-6
        up, down = x.copy(), x.copy()
        up[i] += h
        down[i] -= h
        numeric = (f(up)[0] - f(down)[0]) / (2 * h)
        if abs(numeric - grad[i]) > 1e-4 * max(1.0, abs(numeric)):
            sys.exit(f"gradient {i}: analytic {grad[i]} vs numeric {numeric}")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.path.join(here, "..", "..", "..", "shared", "data", "lagunas2019", "answers_processed_train.json")
    data = lagunas(path)
    dims = 3
    print(f"numpy/scipy L-BFGS-B, Lagunas 2019 training split: {data[5]} stimuli, {len(data[0])} triplets, {dims}-D")
    for family in ("probit", "logistic", "student-t", "probit+lapse+noise"):
        f, size, free, lapse_on = make_objective(family, data, dims)
        check_gradient(f, start(size, free, lapse_on, 99))
        if family == "probit":  # one evaluation with its gradient, beside BM_SpaceObjectiveLagunas3D
            x = start(size, free, lapse_on, 5)
            t = time.perf_counter()
            for _ in range(20):
                f(x)
            print(f"  one probit evaluation with gradient: {(time.perf_counter() - t) / 20 * 1e3:.2f} ms")
        times, evaluations, best = [], [], math.inf
        base = make_objective(family.split("+")[0], data, dims)[0] if "+" in family else None
        for s in range(3):
            x0 = start(size, free, lapse_on, s)
            t = time.perf_counter()
            nfev = 0
            if base:  # as nibrig does: the coordinates by the link alone first, then every part
                first = optimize.minimize(base, x0[:free], jac=True, method="L-BFGS-B",
                                          options={"maxiter": 1000})
                x0[:free], nfev = first.x, first.nfev
            res = optimize.minimize(f, x0, jac=True, method="L-BFGS-B", options={"maxiter": 1000})
            times.append(time.perf_counter() - t)
            evaluations.append(nfev + res.nfev)
            best = min(best, res.fun)
        print(f"  {family:<22} {statistics.median(times):7.3f} s per start (median of 3), best objective {best:.2f},"
              f" {statistics.mean(evaluations):.1f} evaluations a start")


if __name__ == "__main__":
    main()
