#!/usr/bin/env python3
"""tools/autograder-batch on a class of four, graded on stages 01 and 04 (to keep it short):
  correct      the solutions                                      full marks
  broken       camera_y_not_flipped.cpp as its camera             loses stage 01 only
  no_compile   a box.cpp that is not C++                          "build failed", 0, the errors in build.log
  hostile      hostile_forges_results.cpp as its camera: forges results.json, overwrites the reference
               data, prints a fake score table                    exactly what "broken" scores
  copier       a camera that #includes the solution by its absolute path, a box by "../../solutions/..."
               through the kit's include folder                  "build failed", 0: the compile may not read them
and per student only the stage files are compiled and the judge's stage servers linked (the
framework and the judge are built once), a symbolic link in a submission is not followed, and the gradebook
(CSV and JSON) says all of it.
Usage: check_batch.py SOURCE_DIR BUILD_DIR WORK_DIR"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys

source, build, work = (os.path.abspath(a) for a in sys.argv[1:4])
shutil.rmtree(work, ignore_errors=True)
submissions = os.path.join(work, "submissions")
problems = []
files = subprocess.run([os.path.join(build, "bin", "autograder"), "--list-files"], stdout=subprocess.PIPE, text=True,
                       check=True).stdout.split()


def hand_in(student, replace=None, only_replaced=False):
    """The solutions as a student hands them in (bare file names, headers in the stage's folder), with
    replace = {stage file: (text, {extra header name: text})} instead of some (only those, the
    others left as the stubs, when only_replaced)."""
    folder = os.path.join(submissions, student)
    os.makedirs(folder)
    for file in files:
        if only_replaced and file not in replace:
            continue
        if replace and file in replace:
            text, headers = replace[file]
            with open(os.path.join(folder, os.path.basename(file)), "w") as f:
                f.write(text)
            for name, header in headers.items():
                os.makedirs(os.path.join(folder, os.path.dirname(file)), exist_ok=True)
                with open(os.path.join(folder, os.path.dirname(file), name), "w") as f:
                    f.write(header)
            continue
        shutil.copy(os.path.join(source, "solutions", file), folder)
        stage_folder = os.path.join(source, "solutions", os.path.dirname(file))
        for name in os.listdir(stage_folder):
            if name.endswith(".h"):
                os.makedirs(os.path.join(folder, os.path.dirname(file)), exist_ok=True)
                shutil.copy(os.path.join(stage_folder, name), os.path.join(folder, os.path.dirname(file)))


def read(path):
    with open(path) as f:
        return f.read()


camera = "01_camera_rays/camera_rays.cpp"
broken_camera = read(os.path.join(source, "tests/submissions/camera_y_not_flipped.cpp"))
hand_in("correct")
with open(os.path.join(submissions, "correct", "notes.txt"), "w") as f:
    f.write("a file the grader ignores\n")
# A link to a file of the machine's, named like a header: never read.
os.makedirs(os.path.join(submissions, "correct", "01_camera_rays"), exist_ok=True)
os.symlink("/etc/hostname", os.path.join(submissions, "correct", "01_camera_rays", "secret.h"))
hand_in("broken", {camera: (broken_camera, {})})
hand_in("no_compile", {"04_box/box.cpp": ("this is not C++\n", {})})
# The hostile camera includes its honest twin and hostile.h beside it: handed in as headers.
hostile = read(os.path.join(source, "tests/submissions/hostile_forges_results.cpp"))
hostile = hostile.replace('#include "camera_y_not_flipped.cpp"', '#include "camera_y_not_flipped.h"')
hand_in("hostile", {camera: (hostile, {"camera_y_not_flipped.h": broken_camera,
                                       "hostile.h": read(os.path.join(source, "tests/submissions/hostile.h"))})})

# The solutions within a compile's reach: absolutely, and relative to the kit's include folder.
hand_in("copier", {camera: (f'#include "{source}/solutions/{camera}"\n', {}),
                   "04_box/box.cpp": ('#include "../../solutions/04_box/box.cpp"\n', {})}, only_replaced=True)

out = os.path.join(work, "out")
run = subprocess.run([os.path.join(source, "tools", "autograder-batch"), submissions, "--build", build, "--out", out,
                      "--no-build", "-j", "2", "--stage", "01", "--stage", "04"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                     text=True)
print(run.stdout)
if run.returncode != 0:
    sys.exit("FAIL: autograder-batch exited with status %d" % run.returncode)

with open(os.path.join(out, "gradebook.json")) as f:
    book = json.load(f)
rows = {row["student"]: row for row in book["students"]}
with open(os.path.join(out, "gradebook.csv")) as f:
    table = {row["student"]: row for row in csv.DictReader(f)}
if sorted(rows) != ["broken", "copier", "correct", "hostile", "no_compile"] or sorted(table) != sorted(rows):
    problems.append(f"the gradebook lists {sorted(rows)} (JSON) and {sorted(table)} (CSV)")
if book["stages"] != ["01_camera_rays", "04_box"]:
    problems.append(f"the gradebook's stages are {book['stages']}, expected the two graded")
for name, row in rows.items():
    if str(row["score"]) != table[name]["total"] or row["status"] != table[name]["status"] or any(
            str(row["stages"][s]) != table[name][s] for s in book["stages"]):
        problems.append(f"{name}: the CSV and the JSON gradebooks disagree")

correct, broken, hostile_row, no_compile = (rows.get(n, {}) for n in ("correct", "broken", "hostile", "no_compile"))
full = correct.get("max_score", 0)
if correct.get("status") != "graded" or correct.get("score") != full or full <= 0:
    problems.append(f"the solutions scored {correct.get('score')}/{full} ({correct.get('status')})")
if not (broken.get("status") == "graded" and broken["stages"]["01_camera_rays"] < 20 and broken["stages"]["04_box"] == 20):
    problems.append(f"the broken camera scored {broken.get('stages')} ({broken.get('status')}); expected to lose stage 01 only")
if hostile_row.get("status") != "graded" or hostile_row.get("stages") != broken.get("stages"):
    problems.append(f"the hostile camera scored {hostile_row.get('stages')}, its honest twin {broken.get('stages')}")
results = os.path.join(out, "students", "hostile", "results.json")
if os.path.islink(results) or '"forged"' in read(results) or json.loads(read(results))["score"] != hostile_row.get("score"):
    problems.append("the hostile student's results.json is not the judge's")
if no_compile.get("status") != "build failed" or no_compile.get("score") != 0 or no_compile.get("max_score") != full:
    problems.append(f"the code that does not compile: {no_compile}")
if "error" not in read(os.path.join(out, "students", "no_compile", "build.log")):
    problems.append("no_compile's build.log does not show the compiler's errors")
copier = rows.get("copier", {})
if copier.get("status") != "build failed" or copier.get("score") != 0:
    problems.append(f"the submission that includes solutions/ was not refused: {copier}")
copier_log = read(os.path.join(out, "students", "copier", "build.log"))
if copier_log.count("Permission denied") < 2:
    problems.append("copier's build.log does not show both includes of solutions/ denied:\n" + copier_log[-2000:])
correct_log = read(os.path.join(out, "students", "correct", "build.log"))
if "(each compile reads only: " not in correct_log:
    problems.append("correct's build.log does not say what the compile may read")
if "ignored notes.txt" not in correct_log or "ignored 01_camera_rays/secret.h (a symbolic link" not in correct_log:
    problems.append("correct's build.log does not say notes.txt and the link secret.h were ignored")
# Per student: one compile per stage file and one link per stage server of the judge (its
# autograder-stage-server and the -with-grader-... servers of the stages graded on the grader's own
# versions of earlier stages), nothing of the framework.
servers = [n for n in os.listdir(os.path.join(build, "bin")) if re.fullmatch(r"autograder-stage-server(-with-grader[-0-9a-z]*)?", n)]
for name in ("correct", "broken", "hostile"):
    commands = [line for line in read(os.path.join(out, "students", name, "build.log")).splitlines() if line.startswith("$ ")]
    linked = sorted(os.path.basename(c.split(" -o ")[-1].split()[0]) for c in commands if " -o " in c and c.split(" -o ")[-1].split()[0].find("/bin/") >= 0)
    if len(commands) != len(files) + len(servers) or any("framework/src" in c for c in commands) or linked != sorted(servers):
        problems.append(f"{name}: {len(commands)} build commands linking {linked}, expected {len(files)} stage files and "
                        f"one link for each of {sorted(servers)}")
    for report in ("results.json", "grader.log", "output"):
        if not os.path.exists(os.path.join(out, "students", name, report)):
            problems.append(f"{name}: no {report}")
if not book["run"]["submissions_per_minute"] > 0:
    problems.append("the gradebook does not give the throughput")

if problems:
    print("FAIL:\n  " + "\n  ".join(problems))
    sys.exit(1)
print(f"check_batch: correct {full}/{full}, broken and hostile {broken['score']}/{full} alike, no_compile and copier 0 "
      f"(build failed); "
      f"{book['run']['submissions_per_minute']} submissions per minute")
