#!/usr/bin/env python3
"""Measures one of the documentation's tables and writes it, stamped, as a page of its own.

    scripts/measured-tables.py TABLE [--tool build/bin/deepshadow] [--out Documentation/Measured]
                               [--page NAME]
    scripts/measured-tables.py --check FILE...

TABLE is one of the names below; the page is OUT/TABLE.md, or OUT/NAME.md with --page (the same
table measured elsewhere, e.g. frame-budget-gpu on a GPU). The page says what measured it (the command), where (commit,
machine, GL renderer) and when, and ends with a digest of its text: --check recomputes the
digest and fails on a page edited by hand (Documentation.MeasuredTables runs it over every
page). --quick measures a tiny case instead, to test the script itself; its pages are marked
so and --check refuses them in the documentation.
"""
import argparse
import hashlib
import json
import os
import platform
import subprocess
import sys
import tempfile
from datetime import datetime, timezone

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DIGEST = "<!-- measured-tables digest: "


def number(value, digits):
    return "-" if value is None else f"{value:.{digits}f}"


def vtk_mapper_rows(data):
    header = ["scene", "dims", "shaded", "blend", "ours ms", "ours, no skipping", "VTK ms", "ratio",
              "ratio, no skipping", "empty blocks"]
    rows = []
    for r in data["rows"]:
        rows.append([r["scene"], r["dims"], "yes" if r["shade"] else "no", r["blend"],
                     number(r["ours_ms"], 1), number(r["ours_no_skipping_ms"], 1), number(r["vtk_ms"], 1),
                     number(r["ratio"], 2), number(r["ratio_no_skipping"], 2),
                     f"{100 * r['empty_block_fraction']:.0f} %"])
    return header, rows


def shadow_technique_rows(data):
    header = ["scene", "technique", "frame ms", "camera moves", "light moves", "build ms", "MiB",
              "RMSE", "max", "unshadowed RMSE", "nodes avg/max"]
    rows = []
    for r in data["rows"]:
        nodes = ""
        if r.get("dsm_nodes_max"):
            nodes = f"{r['dsm_nodes_avg']:.2f}/{r['dsm_nodes_max']:.0f}"
        build = r["build_ms"]
        rows.append([r["scene"], r["technique"], number(r["camera_ms"], 1), number(r["camera_ratio"], 2),
                     number(r["light_ratio"], 2), number(build, 0) if build > 0 else "-",
                     number(r["shadow_bytes"] / 2**20, 1), number(r["rmse"], 5), number(r["max_abs"], 3),
                     number(r["unshadowed_rmse"], 5), nodes])
    return header, rows


# Issue 42's comparison at equal memory: each technique spec at its bits per light-space
# texel (the registry's TexelBytes times 8; without casting meshes).
BUDGETS = [
    (64, ["dsm:layers=1", "dsm-fixed:dsm-bits=64", "slices:slices=8"]),
    (128, ["dsm:layers=2", "dsm:layers=2:epsilon=0.005", "dsm-fixed:dsm-bits=128", "dsm3",
           "avsm:avsm-nodes=2", "fom:fom-terms=1", "slices:slices=16", "moments:moments=2"]),
    (256, ["dsm:layers=4", "dsm:layers=4:epsilon=0.005", "dsm-fixed", "avsm:avsm-nodes=4", "fom:fom-terms=3",
           "slices", "moments:moments=4", "moments"]),
    (512, ["dsm", "dsm:epsilon=0.005", "dsm-fixed:dsm-bits=512", "avsm", "fom", "slices:slices=64"]),
]
BUDGET_SPECS = ",".join(spec for _, specs in BUDGETS for spec in specs)
BUDGET_ABOUT = ("The deep shadow map, at its error bound (dsm) and at a fixed budget (dsm-fixed), "
                "against its rivals, adaptive volumetric shadow maps (avsm), Fourier opacity maps "
                "(fom), uniform opacity slices (slices) and power moments (moments, MBOIT), and opacity "
                "levels (dsm3), at 64, 128, 256 and 512 bits per light-space texel (moments: 2 at 128, "
                "4 and 6 at 256, in 256 bits' layers), "
                "sorted by error within each budget: the error of the image against the ground truth (CPU, "
                "translucent shadow rays at a quarter step), the error of the shadow term alone at the "
                "first receivers (where the view ray's opacity reaches one half: the technique's CPU "
                "twin against the ground truth's shadows, same march), the frame time ratios to the unshadowed "
                "frame (camera orbiting; key light turning, a rebuild every frame) and the build "
                "time. dsm keeps at most its layers, as few as its epsilon (0.02 by default) needs; at "
                "0.005 it uses more of them. dsm-fixed spends its bits on each texel's smallest bound "
                "that fits.")


def budget_rows(data):
    header = ["scene", "bits / texel", "technique", "RMSE", "max", "receivers RMSE", "receivers max",
              "unshadowed RMSE", "camera moves", "light moves", "build ms", "nodes avg/max"]
    bits = {spec: budget for budget, specs in BUDGETS for spec in specs}
    rows = []
    for r in sorted(data["rows"], key=lambda r: (r["scene"], bits[r["technique"]], r["rmse"])):
        nodes = f"{r['dsm_nodes_avg']:.2f}/{r['dsm_nodes_max']:.0f}" if r.get("dsm_nodes_max") else ""
        rows.append([r["scene"], str(bits[r["technique"]]), r["technique"], number(r["rmse"], 5),
                     number(r["max_abs"], 3), number(r.get("receiver_rmse"), 5),
                     number(r.get("receiver_max"), 3), number(r["unshadowed_rmse"], 5),
                     number(r["camera_ratio"], 2),
                     number(r["light_ratio"], 2), number(r["build_ms"], 0), nodes])
    return header, rows


# Issue 42's frame budget: the uncached deep shadow maps' still frame (camera orbiting, the
# structures built once) over the unshadowed one, against its targets, which differ between a
# CPU rasterizer and a GPU.
FRAME_BUDGET_SPECS = ["dsm", "dsm-fixed:dsm-bits=64", "dsm-fixed:dsm-bits=128", "dsm-fixed", "dsm-fixed:dsm-bits=512"]


def frame_budget_target(technique, renderer):
    software = "llvmpipe" in renderer or "softpipe" in renderer
    return 1.2 if technique.startswith("dsm-fixed") and software else 1.3


def frame_budget_rows(data):
    header = ["scene", "technique", "bits / texel", "unshadowed ms", "shadowed ms", "ratio", "target",
              "within", "RMSE", "unshadowed RMSE"]
    renderer = data.get("gl_renderer", "")
    rows = []
    within = 0
    for r in data["rows"]:
        target = frame_budget_target(r["technique"], renderer)
        ok = r["camera_ratio"] <= target
        within += ok
        bits = str(r["texel_bits"]) if r.get("texel_bits") else "-"
        rows.append([r["scene"], r["technique"], bits, number(r["unshadowed_ms"], 1), number(r["camera_ms"], 1),
                     number(r["camera_ratio"], 2), number(target, 1), "yes" if ok else "no",
                     number(r["rmse"], 5), number(r["unshadowed_rmse"], 5)])
    summary = f"Within the target: {within} of {len(rows)} rows."
    return header, rows, summary


TABLES = {
    "vtk-mapper": {
        "title": "Ours against VTK's vtkGPUVolumeRayCastMapper",
        "about": "Same scenes, views, key light and sample distance in one run; median frame time "
                 "of a slow orbit after warm-up frames. \"No skipping\" takes every sample, as VTK's "
                 "mapper does; \"empty blocks\" is the fraction empty-space skipping jumps over.",
        "args": ["bench", "--size", "512x512", "--frames", "5", "--bench-sizes", "128,256"],
        "quick": ["bench", "--size", "64x64", "--frames", "1", "--bench-sizes", "32"],
        "rows": vtk_mapper_rows,
    },
    "shadow-techniques": {
        "title": "Shadow techniques: run time and error",
        "about": "Per standard scene and technique (each at its defaults, cached where the "
                 "registry's quick sweep caches it): the frame time while only the camera orbits, "
                 "its ratio to the unshadowed frame of the same run and the ratio while the key "
                 "light turns (a rebuild every frame), the build time, the shadow memory, and the "
                 "error against the ground truth (CPU, translucent shadow rays at a quarter step, "
                 "coloured for coloured techniques) at the error size.",
        "args": ["shadow-bench", "--size", "256x256", "--error-size", "256x256", "--frames", "5"],
        "quick": ["shadow-bench", "--scenes", "box", "--techniques", "shadowmap,dsm", "--size", "64x64",
                  "--error-size", "32x32", "--frames", "1"],
        "rows": shadow_technique_rows,
    },
    "shadow-budgets": {
        "title": "Shadow representations at equal memory",
        "about": BUDGET_ABOUT,
        "args": ["shadow-bench", "--scenes", "head,clouds,hybrid-ground", "--size", "256x256",
                 "--error-size", "128x128", "--frames", "3", "--receiver-error", "--techniques", BUDGET_SPECS],
        "charts": True,
        "quick": ["shadow-bench", "--scenes", "box", "--techniques", "dsm:layers=1,avsm:avsm-nodes=2",
                  "--size", "32x32", "--error-size", "16x16", "--frames", "1", "--receiver-error"],
        "rows": budget_rows,
    },
    "shadow-budgets-mr": {
        "title": "Shadow representations at equal memory: a real MR",
        "about": "As the standard scenes' page, on the Colin27 brain MRI (Debian's mricron-data, "
                 "181x217x181, the tool's default preset for the file) under a key light from the "
                 "upper right front. " + BUDGET_ABOUT,
        "args": ["shadow-bench", "--volume", "/usr/share/mricron/templates/ch2.nii.gz", "--size", "256x256",
                 "--error-size", "128x128", "--frames", "3", "--receiver-error", "--techniques", BUDGET_SPECS],
        "charts": True,
        "quick": ["shadow-bench", "--volume", "/usr/share/mricron/templates/ch2.nii.gz", "--techniques",
                  "dsm-fixed:dsm-bits=64", "--size", "32x32", "--error-size", "16x16", "--frames", "1"],
        "rows": budget_rows,
    },
    "frame-budget": {
        "title": "Frame budget of the uncached deep shadow maps",
        "about": "Per standard scene at 512x512: the frame while only the camera orbits (the "
                 "shadow structures built once, looked up at every sample) with the deep shadow map "
                 "at its error bound (dsm) and at a fixed budget (dsm-fixed, 64 to 512 bits per "
                 "texel), over the unshadowed frame of the same run, against issue 42's targets: on "
                 "a CPU rasterizer (llvmpipe) at most 1.2 for dsm-fixed and 1.3 for dsm, on a GPU at "
                 "most 1.3 for both; and the image's error against the ground truth (CPU, "
                 "translucent shadow rays at a quarter step) at 128x128. Single runs: this "
                 "machine's frame times vary by several per cent between runs.",
        "args": ["shadow-bench", "--scenes", "box,bucky,rods,clouds,spheres,head,sparse", "--size", "512x512",
                 "--error-size", "128x128", "--frames", "5", "--techniques", ",".join(FRAME_BUDGET_SPECS)],
        "quick": ["shadow-bench", "--scenes", "box", "--techniques", "dsm,dsm-fixed:dsm-bits=64", "--size",
                  "32x32", "--error-size", "16x16", "--frames", "1"],
        "rows": frame_budget_rows,
    },
}


def git(*args):
    try:
        return subprocess.run(["git", "-C", ROOT, *args], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def machine():
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    memory = ""
    try:
        pages = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
        memory = f", {pages / 2**30:.0f} GiB"
    except (ValueError, OSError):
        pass
    distribution = ""
    try:
        with open("/etc/os-release") as f:
            fields = dict(line.rstrip("\n").split("=", 1) for line in f if "=" in line)
        distribution = fields.get("PRETTY_NAME", "").strip('"') + ", "
    except OSError:
        pass
    return f"{distribution}{cpu}, {os.cpu_count()} cores{memory}"


def digest(text):
    return hashlib.sha256(text.encode()).hexdigest()


def page(table, name, spec, data, command, quick):
    header, rows, *summary = spec["rows"](data)
    commit = git("rev-parse", "--short", "HEAD") or "unknown"
    changed = git("diff", "--name-only", "HEAD").splitlines()
    if changed:
        commit += " with uncommitted changes to " + ", ".join(changed[:5]) + (", ..." if len(changed) > 5 else "")
    stamp = datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    lines = [
        f"# {spec['title']}" + (" (quick test run, not a measurement)" if quick else ""),
        "",
        f"Written by `scripts/measured-tables.py {table}" + (f" --page {name}" if name != table else "") +
        "`: do not edit by hand, run it again.",
        f"Measured at commit {commit}, {stamp}, on {machine()}; GL: {data.get('gl_renderer', 'unknown')}.",
        f"Command: `{command}`.",
        "",
        spec["about"],
        "",
        "| " + " | ".join(header) + " |",
        "|" + "---|" * len(header),
    ]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    if summary:
        lines += ["", *summary]
    if spec.get("charts"):
        lines += ["", "Per scene, the image's RMSE against bits per texel and against the camera-only "
                  "frame ratio, one series per technique, the Pareto front dashed:", ""]
        for scene in dict.fromkeys(r["scene"] for r in data["rows"]):
            lines.append(f"![{scene}]({name}/{scene}.png)")
    text = "\n".join(lines) + "\n"
    return text + DIGEST + digest(text) + (" quick" if quick else "") + " -->\n"


def check(paths, allow_quick):
    bad = 0
    for path in paths:
        with open(path) as f:
            text = f.read()
        at = text.rfind(DIGEST)
        if at < 0:
            print(f"{path}: no digest line (not written by scripts/measured-tables.py)")
            bad += 1
            continue
        fields = text[at + len(DIGEST):].split()
        if fields[0] != digest(text[:at]):
            print(f"{path}: edited by hand since it was measured (run scripts/measured-tables.py again)")
            bad += 1
        elif "quick" in fields[1:2] and not allow_quick:
            print(f"{path}: a quick test run, not a measurement")
            bad += 1
    return 1 if bad else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("table", nargs="?", choices=sorted(TABLES))
    parser.add_argument("--tool", default=os.path.join(ROOT, "build", "bin", "deepshadow"))
    parser.add_argument("--out", default=os.path.join(ROOT, "Documentation", "Measured"))
    parser.add_argument("--page", help="the page's file name without .md (default: the table's name; "
                        "e.g. frame-budget-gpu for a GPU's run)")
    parser.add_argument("--quick", action="store_true", help="a tiny case, to test this script")
    parser.add_argument("--check", nargs="+", metavar="FILE", help="check pages' digests")
    parser.add_argument("--allow-quick", action="store_true", help="with --check: accept quick pages")
    options = parser.parse_args()
    if options.check:
        return check(options.check, options.allow_quick)
    if not options.table:
        parser.error("give a table or --check")
    spec = TABLES[options.table]
    name = options.page or options.table
    args = spec["quick"] if options.quick else spec["args"]
    os.makedirs(options.out, exist_ok=True)
    if spec.get("charts"):
        charts = os.path.join(options.out, name)
        os.makedirs(charts, exist_ok=True)
        args = [*args, "--charts", charts]
    with tempfile.TemporaryDirectory() as work:
        result = os.path.join(work, "result.json")
        # The tool prints its rows as it goes: progress on a long run.
        if subprocess.run([options.tool, *args, "--json", result], stdout=sys.stderr).returncode != 0:
            print(f"measured-tables: {options.tool} {' '.join(args)} failed", file=sys.stderr)
            return 1
        with open(result) as f:
            data = json.load(f)
    command = "deepshadow " + " ".join(a if a != options.out and not a.startswith(options.out + "/")
                                       else os.path.relpath(a, ROOT) for a in args)
    path = os.path.join(options.out, name + ".md")
    with open(path, "w") as f:
        f.write(page(options.table, name, spec, data, command, options.quick))
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
