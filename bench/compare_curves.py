#!/usr/bin/env python3
"""Largest differences between two builds' stiffness curves on every shipped problem.

    bench/compare_curves.py OLD/curve_digits NEW/curve_digits

Six variants per problem (the default, rigid and per-pair rack body, the constant
contact term, 7 positions per period, a tip relief). Per variant: the largest relative
difference of k_min/k_max/k_mean, of any sample's stiffness, and the largest absolute
difference of any pair's load share; "identical" when every printed digit agrees.
"""
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
PROBLEMS = ["gantry_axis", "large_module", "rack_railway", "rack_railway_paper", "ship_lift"]
VARIANTS = [[], ["effects.rack_span=rigid"], ["effects.rack_span=per_pair"], ["effects.hertz=linear"],
            ["numerics.positions_per_period=7"], ["pinion.tip_relief={amount: 42 um, length: 1.72}"]]


def curve(program, problem, variant):
    run = subprocess.run([program, str(ROOT / "problems" / f"{problem}.yaml")] + variant,
                         capture_output=True, text=True)
    return [line.split() for line in run.stdout.splitlines()] if run.returncode == 0 else None


def main(old, new):
    for problem in PROBLEMS:
        for variant in VARIANTS:
            a, b = curve(old, problem, variant), curve(new, problem, variant)
            name = f"{problem:20s} {' '.join(variant):48s}"
            if a is None or b is None or len(a) != len(b):
                print(name, "failed or a different number of samples")
                continue
            k = max(abs(float(x) - float(y)) / abs(float(x)) for x, y in zip(a[0][1:4], b[0][1:4]))
            sample = max(abs(float(x[2]) - float(y[2])) / abs(float(x[2])) for x, y in zip(a[1:], b[1:]))
            share = max((abs(float(u) - float(v)) for x, y in zip(a[1:], b[1:]) if len(x) == len(y)
                         for u, v in zip(x[5::2], y[5::2])), default=0.0)
            same = "identical" if a == b else ""
            print(f"{name} k {k:.1e}  samples {sample:.1e}  load shares {share:.1e}  {same}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
