"""bench/stereo/scaling_table.py: medians per dataset, the aside set apart, log-log slopes."""

import pathlib
import subprocess
import sys

SCRIPT = pathlib.Path(__file__).parents[2] / "bench/stereo/scaling_table.py"
HEADER = ("scene pixels flat_energy c2f_energy flat_bad_nonocc c2f_bad_nonocc flat_bad_all "
          "c2f_bad_all flat_seconds c2f_seconds c2f_reach_flat_seconds reach_ratio "
          "deadline_error_flat deadline_error_c2f deadline_error_reduction sgbm_bad_nonocc "
          "sgbm_bad_all sgbm_seconds flat_reason c2f_reason labels prep_seconds threads "
          "c2f_band_seconds band_ratio prep_one_thread_seconds prep_peak_mib flat_peak_mib "
          "c2f_peak_mib memory_gib").split()


def row(scene, pixels, labels, flat_seconds, band_seconds, prep=(4.0, 2.0), peaks=(10, 20, 30)):
    values = dict.fromkeys(HEADER, "0")
    values.update(scene=scene, pixels=str(pixels), labels=str(labels),
                  flat_seconds=str(flat_seconds), c2f_seconds=str(flat_seconds),
                  c2f_band_seconds=band_seconds, flat_reason="converged", c2f_reason="converged",
                  deadline_error_flat="0.2", deadline_error_c2f="0.1",
                  prep_one_thread_seconds=str(prep[0]), prep_seconds=str(prep[1]),
                  prep_peak_mib=str(peaks[0]), flat_peak_mib=str(peaks[1]),
                  c2f_peak_mib=str(peaks[2]))
    return "\t".join(HEADER) + "\n" + "\t".join(values[k] for k in HEADER) + "\n"


def write(folder, scene, text):
    folder.mkdir(parents=True, exist_ok=True)
    (folder / (scene.replace("/", "-") + ".tsv")).write_text(text)


def table(out, *arguments):
    done = subprocess.run([sys.executable, str(SCRIPT), str(out), *arguments],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_medians_aside_and_slopes(tmp_path):
    # Flat time grows as (pixels x labels)^1.5: 1, 8 and 64 s at 1M, 4M and 16M pixel-labels.
    scenes = [("Art", 10000, 100, 1.0), ("middlebury2014/A", 40000, 100, 8.0),
              ("middlebury2014/B", 160000, 100, 64.0), ("middlebury2014/C", 40000, 100, 8.0)]
    for scene, pixels, labels, seconds in scenes:
        for config in ("whole", "same", "prep"):
            band = "nan" if scene == "middlebury2014/B" and config == "same" else str(seconds / 4)
            write(tmp_path / config, scene, row(scene, pixels, labels, seconds, band))
    out = table(tmp_path, "--aside", "middlebury2014/C")
    lines = out.splitlines()
    # Middlebury 2014 without the aside scene: A and B; B never came within 1e-4 of flat-same.
    m2014 = next(line for line in lines if line.startswith("| **Middlebury 2014 Q** (2)"))
    assert "| 10.0 |" in m2014  # median pixels x labels of 4M and 16M
    assert "| 4.00 / 2.00 | 2.00 |" in m2014  # preparation at 1 / 2 threads and the speedup
    assert "| never |" in m2014  # the median of 0.25 and infinity
    assert "| 30 |" in m2014  # the peak: the largest of preparation, flat and C2F
    assert next(line for line in lines if line.startswith("| **set aside** (1)"))
    assert any(line.startswith("| middlebury2014/C (aside) |") for line in lines)
    assert "flat TSGO (whole moves) to converge against pixels x labels: 1.50 (4 scenes)" in out
    # The scene that never came within 1e-4 is left out of that slope.
    assert "flat-same's final energy against pixels x labels: 1.50 (3 scenes)" in out


def test_rows_without_header_and_fewer_columns(tmp_path):
    # run-middlebury's rows have no header; earlier ones have 25 columns.
    write(tmp_path / "whole", "Art", row("Art", 10000, 100, 2.0, "0.5"))
    old = tmp_path / "old.tsv"
    old.write_text("\t".join(row("Art", 10000, 100, 4.0, "1.0").splitlines()[1].split("\t")[:25]))
    out = table(tmp_path, str(old))
    assert "| Art | 1.0 | - / - | - | 2.0 | 4.0 |" in out


def test_no_rows_is_an_error(tmp_path):
    done = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path)], capture_output=True,
                          text=True, timeout=60)
    assert done.returncode != 0
    assert "no rows under" in done.stderr
