#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""Douady and Couder's threshold model of phyllotaxis on the growth of configs/phyllotaxis_dome*.yaml (docs/networks.md,
"An inhibition field of Douady and Couder's range"), an idealisation to compare the tissue runs with.

Primordia are points in the plane that move away from the summit with the meristem field's speed
v = k(r) r, k(r) = kc + (kp - kc)(1 + tanh((r - R)/w))/2 (docs/growth.md). Each inhibits around it with the
field of a disk of radius a = a0 r / R0 (the clone, growing with the tissue) held at IP in a medium with
decay length lam: IP K0(s / lam) / K0(a / lam) at distance s from its centre (s >= a). Every dt, where the
summed inhibition on the circle r = R0 is below 1, a new primordium forms at the minimum, displaced by a
uniform draw in [-noise/2, noise/2] degrees (the angular size of a cell), unless it is closer than sep to
a primordium already there (the same peak); it starts inhibiting tau later (the time an auxin peak takes to
reach the threshold). The start is one primordium, or --ring N of them evenly spaced (jittered by the
noise), as the tissue's first solves make. IP is set from Gamma = d / R0, d the distance at which a lone young
primordium's inhibition is 1: IP = K0(a0 / lam) / K0(Gamma R0 / lam). Prints, per Gamma, over the seeds: primordia,
mean plastochron, folded divergences (min(d, 360 - d)) after the first `skip`: mean, s.d., the shares
within 20 degrees of 137.5, at 160 or more, below 90. Usage:
  /usr/bin/python3 scripts/douady_couder.py --lam 0.5 --tau 0.2 --noise 18 1.0 1.5 2.0  (needs SciPy)
"""
import argparse
import math

import numpy as np
from scipy.special import k0


def growth_rate(r, R=1.5, w=0.3, kc=0.05, kp=0.15):
    return kc + (kp - kc) * (1 + math.tanh((r - R) / w)) / 2


def run(lam, IP, a0, R0, dt, tend, noise, tau, sep, seed, grow=True, ring_start=1):
    rng = np.random.default_rng(seed)
    th = np.radians(np.arange(0.0, 360.0, 1.0))
    ring = np.stack([R0 * np.cos(th), R0 * np.sin(th)], 1)
    # distance, angle, time it starts inhibiting: ring_start primordia evenly spaced (and jittered) at t = 0
    start = [2 * math.pi * j / ring_start + math.radians(rng.uniform(-noise / 2, noise / 2)) for j in range(ring_start)]
    prim = [[R0, a, 0.0] for a in start]
    rec = [(0.0, math.degrees(a)) for a in start]
    t = 0.0
    while t < tend:
        for p in prim:  # midpoint rule for dr/dt = k(r) r
            r = p[0]
            r1 = r + 0.5 * dt * growth_rate(r) * r
            p[0] = r + dt * growth_rate(r1) * r1
        t += dt
        act = [p for p in prim if p[2] <= t and p[0] < 8.0]  # beyond 8 the field at R0 is below 1e-5
        P = np.array([[p[0] * math.cos(p[1]), p[0] * math.sin(p[1])] for p in act]).reshape(-1, 2)
        A = np.array([a0 * (p[0] / R0 if grow else 1.0) for p in act])
        s = np.maximum(np.linalg.norm(ring[:, None, :] - P[None, :, :], axis=2), A[None, :])
        E = (IP * k0(s / lam) / k0(A / lam)[None, :]).sum(1)
        for i in np.argsort(E):
            if E[i] >= 1.0:
                break
            ang = th[i] + math.radians(rng.uniform(-noise / 2, noise / 2))
            x, y = R0 * math.cos(ang), R0 * math.sin(ang)
            if any(math.hypot(x - p[0] * math.cos(p[1]), y - p[0] * math.sin(p[1])) < sep for p in prim):
                continue
            prim.append([R0, ang, t + tau])
            rec.append((t, math.degrees(ang)))
    return rec


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("gamma", type=float, nargs="+", help="d / R0")
    ap.add_argument("--lam", type=float, default=0.5, help="decay length of the inhibitor")
    ap.add_argument("--R0", type=float, default=1.85, help="radius where primordia form")
    ap.add_argument("--a0", type=float, default=0.35, help="radius of a young primordium (one cell)")
    ap.add_argument("--tau", type=float, default=0.2, help="delay before a new primordium inhibits")
    ap.add_argument("--noise", type=float, default=18.0, help="placement noise, degrees (full width)")
    ap.add_argument("--sep", type=float, default=1.6, help="min_separation")
    ap.add_argument("--dt", type=float, default=0.1)
    ap.add_argument("--end", type=float, default=60.0)
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--skip", type=int, default=5, help="divergences left out at the start")
    ap.add_argument("--fixed-clone", action="store_true", help="a = a0 at any distance")
    ap.add_argument("--ring", type=int, default=1, help="start with this many primordia evenly around R0")
    args = ap.parse_args()
    for gamma in args.gamma:
        IP = k0(args.a0 / args.lam) / k0(gamma * args.R0 / args.lam)
        folds, counts, plast = [], [], []
        for seed in range(args.seeds):
            rec = run(args.lam, IP, args.a0, args.R0, args.dt, args.end, args.noise, args.tau, args.sep, seed,
                      grow=not args.fixed_clone, ring_start=args.ring)
            div = [(b[1] - a[1]) % 360.0 for a, b in zip(rec, rec[1:])]
            folds += [min(d, 360.0 - d) for d in div][args.skip:]
            counts.append(len(rec))
            plast += list(np.diff([r[0] for r in rec])[args.skip:])
        f = np.array(folds)
        print(f"Gamma {gamma} (IP {IP:.3g}): primordia {counts}, plastochron {np.mean(plast):.2f}, "
              f"divergence {f.mean():.1f} / s.d. {f.std():.1f}, ~137.5 {np.mean(abs(f - 137.5) <= 20):.2f}, "
              f">=160 {np.mean(f >= 160):.2f}, <90 {np.mean(f < 90):.2f}", flush=True)


if __name__ == "__main__":
    main()
