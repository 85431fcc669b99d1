#!/usr/bin/env python3
"""Rewrites the result tables of docs/physics-accuracy.md from one sweep's results.csv.

    python3 bench/physics-compare/scripts/report_tables.py docs/physics-accuracy/results.csv docs/physics-accuracy.md

Every table row under the headers below is replaced (the prose around them is not): the
presets are the sweep points fast = 30 Hz × 2, balanced = 60 Hz × 4, precise = 120 Hz × 4
(rapier at the same rate with as many solver iterations).
"""
import csv
import sys

PRESETS = [("fast", 30, 2), ("balanced", 60, 4), ("precise", 120, 4)]
MAIN = ["free_fall", "bounce", "sliding", "stack", "pyramid", "tunneling", "far_origin",
        "mass_ratio", "incline", "rolling", "long_run", "tiny_huge", "big_pyramid",
        "poured_spheres", "degenerate_hulls"]
ISSUE15 = ["rotation_energy", "wide_wall_ccd", "restitution_ladder", "elastic_crowd",
           "mass_ratio_ladder", "size_ladder", "frictionless_stacks", "frictionless_random",
           "frictionless_drops"]
JOINTS = ["pendulum", "chain", "hinge_motor", "prismatic_limit", "bridge", "ragdolls"]
MAIN_HEADER = "| scene | preset | Onyx error | rapier error | Onyx ms/sim-s | rapier ms/sim-s | Onyx/rapier cost |"
JOINT_ERR_HEADER = "| scene (error) | fast Onyx | fast rapier | balanced Onyx | balanced rapier | precise Onyx | precise rapier |"
JOINT_COST_HEADER = "| scene | joints | fast × | balanced × | balanced µs per joint-step, Onyx / rapier | precise × |"


def num(x, digits):
    """`digits` significant figures from 0.01 to 1000, else one decimal in e-notation."""
    if x == 0:
        return "0"
    if 0.01 <= abs(x) < 1000:
        return f"{x:.{digits}g}"
    m, e = f"{x:.1e}".split("e")
    return f"{m}e{'+' if int(e) >= 0 else '-'}{abs(int(e))}"


def load(path):
    rows = {}
    for r in csv.DictReader(open(path)):
        rows[(r["scene"], r["engine"], int(r["hz"]), int(r["iterations"]))] = r
    return rows


def main_rows(rows, scenes):
    out = []
    for s in scenes:
        for name, hz, it in PRESETS:
            o, r = rows[(s, "onyx", hz, it)], rows[(s, "rapier", hz, it)]
            ratio = float(o["ms_per_sim_second"]) / float(r["ms_per_sim_second"])
            out.append(f"| {s} | {name} | {num(float(o['error']), 3)} | {num(float(r['error']), 3)} "
                       f"| {num(float(o['ms_per_sim_second']), 3)} | {num(float(r['ms_per_sim_second']), 3)} "
                       f"| {ratio:.2f} |")
    return out


def joint_err_rows(rows, old):
    out = []
    for s in JOINTS:
        label = next((l.split("|")[1].strip() for l in old if l.startswith(f"| {s} (")), s)
        cells = []
        for _, hz, it in PRESETS:
            for e in ("onyx", "rapier"):
                cells.append(num(float(rows[(s, e, hz, it)]["error"]), 2))
        out.append(f"| {label} | " + " | ".join(cells) + " |")
    return out


def joint_cost_rows(rows):
    out = []
    for s in JOINTS:
        ratios = []
        for _, hz, it in PRESETS:
            o, r = rows[(s, "onyx", hz, it)], rows[(s, "rapier", hz, it)]
            x = float(o["ms_per_sim_second"]) / float(r["ms_per_sim_second"])
            ratios.append(f"**{x:.2f}**" if x > 1 else f"{x:.2f}")
        o, r = rows[(s, "onyx", 60, 4)], rows[(s, "rapier", 60, 4)]
        joints = int(o["joints"])
        per = lambda x: float(x["ms_per_step"]) * 1000 / joints
        out.append(f"| {s} | {joints} | {ratios[0]} | {ratios[1]} | {per(o):.2f} / {per(r):.2f} | {ratios[2]} |")
    return out


def replace_table(lines, header, make):
    i = lines.index(header)
    j = i + 2
    while j < len(lines) and lines[j].startswith("|"):
        j += 1
    lines[i + 2:j] = make(lines[i + 2:j])


def main():
    rows = load(sys.argv[1])
    lines = open(sys.argv[2]).read().split("\n")
    starts = [k for k, l in enumerate(lines) if l == MAIN_HEADER]
    # The first main-format table is the tuned scenes', the second issue 15's.
    for k, scenes in zip(starts, [MAIN, ISSUE15]):
        j = k + 2
        while lines[j].startswith("|"):
            j += 1
        lines[k + 2:j] = main_rows(rows, scenes)
    replace_table(lines, JOINT_ERR_HEADER, lambda old: joint_err_rows(rows, old))
    replace_table(lines, JOINT_COST_HEADER, lambda old: joint_cost_rows(rows))
    open(sys.argv[2], "w").write("\n".join(lines))


if __name__ == "__main__":
    main()
