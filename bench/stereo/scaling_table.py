"""The scaling table of bench/stereo/run-scaling: per-dataset medians and log-log slopes.

usage: python3 bench/stereo/scaling_table.py OUT_DIR [--aside SCENE,...] [SAME_ROWS.tsv ...]

Reads the c2f-bench-stereo rows (with headers) of OUT_DIR/whole/*.tsv (C2F against flat TSGO
with whole moves), OUT_DIR/same/*.tsv (C2F against flat with the same near and shift moves) and
OUT_DIR/prep/*.tsv (data preparation at 1 and 2 threads). Further rows files fill in the `same`
baseline for scenes OUT_DIR/same lacks (e.g. an earlier run-middlebury of that configuration;
their columns may be fewer). Prints markdown: one line per dataset with medians, one for the
scenes set aside (--aside: kept out of every choice of parameters, reported apart and not in
their dataset's medians), one per scene, and the slopes of log time against log(pixels x
labels) over all scenes.
"""

import math
import statistics
import sys
from pathlib import Path


# c2f-bench-stereo's columns in its order (its --header): rows without a header line (as
# run-middlebury writes them) are read with these names; older rows have fewer columns.
BENCH_COLUMNS = (
    "scene pixels flat_energy c2f_energy flat_bad_nonocc c2f_bad_nonocc flat_bad_all c2f_bad_all "
    "flat_seconds c2f_seconds c2f_reach_flat_seconds reach_ratio deadline_error_flat "
    "deadline_error_c2f deadline_error_reduction sgbm_bad_nonocc sgbm_bad_all sgbm_seconds "
    "flat_reason c2f_reason labels prep_seconds threads c2f_band_seconds band_ratio "
    "prep_one_thread_seconds prep_peak_mib flat_peak_mib c2f_peak_mib memory_gib").split()


def read_rows(paths):
    """Rows by scene from c2f-bench-stereo's tab-separated files (later files win)."""
    rows = {}
    for path in paths:
        header = BENCH_COLUMNS
        for line in open(path):
            fields = line.rstrip("\n").split("\t")
            if fields[0] == "scene":
                header = fields
            elif fields[0]:
                if len(fields) > len(header):
                    raise SystemExit(f"scaling_table: {path}: a row of {len(fields)} fields")
                rows[fields[0]] = dict(zip(header, fields))
    return rows


def number(row, key):
    """The field as a float; NaN when the row or the column is missing or not a number."""
    if row is None or key not in row:
        return math.nan
    try:
        return float(row[key])
    except ValueError:
        return math.nan


def band_seconds(row):
    """When C2F came within 1e-4 of flat's final energy; infinite when it never did."""
    value = number(row, "c2f_band_seconds")
    return math.inf if row is not None and math.isnan(value) else value


def dataset(scene):
    if scene.startswith("middlebury2014/"):
        return "Middlebury 2014 Q"
    if scene.startswith("kitti2015/"):
        return "KITTI 2015"
    if scene == "opencv-doc/aloe":
        return "Aloe full size"
    return "Middlebury 2005/2006 third"


def median(values):
    values = [v for v in values if not math.isnan(v)]
    return statistics.median(values) if values else math.nan


def text(value, digits=2):
    if math.isnan(value):
        return "-"
    if math.isinf(value):
        return "never"
    return f"{value:.{digits}f}"


def scene_line(scene, whole, same, prep):
    pixels = number(whole or same, "pixels")
    labels = number(whole or same, "labels")
    flat_whole = number(whole, "flat_seconds")
    flat_same = number(same, "flat_seconds")
    to_whole = band_seconds(whole)
    to_same = band_seconds(same)
    peaks = [number(r, k) for r in (whole, same) for k in ("flat_peak_mib", "c2f_peak_mib")]
    peaks.append(number(prep, "prep_peak_mib"))
    prep_one = number(prep, "prep_one_thread_seconds")
    prep_two = number(prep, "prep_seconds")
    return {
        "scene": scene,
        "dataset": dataset(scene),
        "pixels": pixels,
        "labels": labels,
        "size": pixels * labels,
        "prep_one": prep_one,
        "prep_two": prep_two,
        "prep_speedup": prep_one / prep_two,
        "flat_whole": flat_whole,
        "flat_whole_converged": whole is not None and whole.get("flat_reason") == "converged",
        "flat_same": flat_same,
        "flat_same_converged": same is not None and same.get("flat_reason") == "converged",
        "c2f": number(same or whole, "c2f_seconds"),
        "to_whole": to_whole,
        "ratio_whole": to_whole / flat_whole,
        "to_same": to_same,
        "ratio_same": to_same / flat_same,
        "error_whole": number(whole, "deadline_error_flat"),
        "error_c2f_whole": number(whole, "deadline_error_c2f"),
        "error_same": number(same, "deadline_error_flat"),
        "error_c2f_same": number(same, "deadline_error_c2f"),
        "peak": max((p for p in peaks if not math.isnan(p)), default=math.nan),
    }


COLUMNS = [
    ("pixels x labels (M)", lambda r: r["size"] / 1e6, 1),
    ("prep s 1 / 2 threads", None, None),
    ("speedup", lambda r: r["prep_speedup"], 2),
    ("flat whole s", lambda r: r["flat_whole"], 1),
    ("flat same s", lambda r: r["flat_same"], 1),
    ("C2F s", lambda r: r["c2f"], 1),
    ("C2F to flat whole E (1e-4): ratio", lambda r: r["ratio_whole"], 3),
    ("C2F to flat same E (1e-4): ratio", lambda r: r["ratio_same"], 3),
    ("deadline error flat whole / C2F", None, None),
    ("deadline error flat same / C2F", None, None),
    ("peak MiB", lambda r: r["peak"], 0),
]


def cells(lines, pick):
    """The table cells of one row (a scene, or the medians of a dataset's scenes)."""
    out = []
    for name, get, digits in COLUMNS:
        if name.startswith("prep s"):
            out.append(f"{text(pick('prep_one'))} / {text(pick('prep_two'))}")
        elif name.startswith("deadline error flat whole"):
            out.append(f"{percent(pick('error_whole'))} / {percent(pick('error_c2f_whole'))}")
        elif name.startswith("deadline error flat same"):
            out.append(f"{percent(pick('error_same'))} / {percent(pick('error_c2f_same'))}")
        else:
            out.append(text(median([get(r) for r in lines]), digits))
    return out


def percent(value):
    return "-" if math.isnan(value) else f"{100 * value:.1f}%"


def slope(lines, key):
    """Least-squares slope of log(key) against log(pixels x labels), and the scenes it used."""
    points = [(math.log(r["size"]), math.log(r[key])) for r in lines
              if r[key] > 0 and math.isfinite(r[key]) and r["size"] > 0]
    if len(points) < 2:
        return math.nan, len(points)
    mean_x = sum(x for x, _ in points) / len(points)
    mean_y = sum(y for _, y in points) / len(points)
    sxx = sum((x - mean_x) ** 2 for x, _ in points)
    sxy = sum((x - mean_x) * (y - mean_y) for x, y in points)
    return sxy / sxx, len(points)


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    out = Path(sys.argv[1])
    extra = sys.argv[2:]
    aside = set()
    if extra[:1] == ["--aside"]:
        if len(extra) < 2:
            raise SystemExit("scaling_table: --aside: expected SCENE,SCENE,...")
        aside = set(extra[1].split(","))
        extra = extra[2:]
    whole = read_rows(sorted((out / "whole").glob("*.tsv")))
    same = read_rows([Path(p) for p in extra] + sorted((out / "same").glob("*.tsv")))
    prep = read_rows(sorted((out / "prep").glob("*.tsv")))
    scenes = set(whole) | set(same)
    if not scenes:
        raise SystemExit(f"scaling_table: no rows under {out}/whole or {out}/same")
    lines = [scene_line(s, whole.get(s), same.get(s), prep.get(s)) for s in scenes]
    # Datasets from the smallest to the largest, scenes by name within them.
    order = {d: median([r["size"] for r in lines if r["dataset"] == d])
             for d in {r["dataset"] for r in lines}}
    lines.sort(key=lambda r: (order[r["dataset"]], r["dataset"], r["scene"]))
    header = ["dataset (scenes)"] + [name for name, _, _ in COLUMNS]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    groups = [(name, [r for r in lines if r["dataset"] == name and r["scene"] not in aside])
              for name in sorted(order, key=lambda d: order[d])]
    groups.append(("set aside", [r for r in lines if r["scene"] in aside]))
    for name, group in groups:
        if group:
            row = cells(group, lambda key, group=group: median([r[key] for r in group]))
            print(f"| **{name}** ({len(group)}) | " + " | ".join(row) + " |")
    print()
    print("Per scene (a flat time marked * did not converge within the time limit):")
    print()
    print("| scene | " + " | ".join(header[1:]) + " |")
    print("|" + "---|" * len(header))
    for r in lines:
        row = cells([r], lambda key, r=r: r[key])
        if not r["flat_whole_converged"] and not math.isnan(r["flat_whole"]):
            row[3] += "*"
        if not r["flat_same_converged"] and not math.isnan(r["flat_same"]):
            row[4] += "*"
        mark = " (aside)" if r["scene"] in aside else ""
        print(f"| {r['scene']}{mark} | " + " | ".join(row) + " |")
    print()
    for key, what in [("prep_one", "data preparation, 1 thread"),
                      ("prep_two", "data preparation, 2 threads"),
                      ("flat_whole", "flat TSGO (whole moves) to converge"),
                      ("flat_same", "flat with near and shift moves to converge"),
                      ("c2f", "C2F to converge"),
                      ("to_same", "C2F to within 1e-4 of flat-same's final energy")]:
        value, used = slope(lines, key)
        print(f"- log-log slope of {what} against pixels x labels: {text(value)} "
              f"({used} scenes)")


if __name__ == "__main__":
    main()
