#!/usr/bin/env python3
"""compare_check_results.py DESKTOP PAGE [--needs KIND,...]: whether two results.json files (Gradescope's shape) give the same verdict:
`meshedit grade --visible-only --results DESKTOP` and the page's Check my work (<script id="check-results">, written by
page_driver.py --check-results PAGE) for the same files and suite.

Compared word for word: the score, the max_score and the output of the whole report, and each test's number, name,
score, max_score, status, visibility and output, in order. Not compared: execution_time (the clock) and the pictures of
failing neighbourhoods that the desktop's grader appends to a failed test's Markdown (the page has no headless
renderer): each test's output is taken up to its picture. So that the comparison means something, the desktop's
report must have a test of each KIND of --needs (passed, failed, time-limit: a test stopped at its time limit); a
failed one when --needs is not given.

Exit status: 0 the same, 1 not (each difference printed).
"""
import json
import sys

PICTURE = "\n\n![test "
TOP_FIELDS = ("score", "max_score", "output", "output_format", "test_output_format", "visibility")
TEST_FIELDS = ("number", "name", "score", "max_score", "status", "visibility", "output")


def without_picture(text):
    at = text.find(PICTURE)
    return text if at < 0 else text[:at]


def main():
    args = sys.argv[1:]
    needs = ["failed"]
    if len(args) == 4 and args[2] == "--needs":
        needs = args[3].split(",")
        args = args[:2]
    if len(args) != 2:
        print(__doc__.split("\n")[0])
        return 1
    with open(args[0]) as f:
        desktop = json.load(f)
    with open(args[1]) as f:
        page = json.load(f)
    differences = []
    for field in TOP_FIELDS:
        if desktop.get(field) != page.get(field):
            differences.append("%s: desktop %r, page %r" % (field, desktop.get(field), page.get(field)))
    desktop_tests, page_tests = desktop.get("tests", []), page.get("tests", [])
    if len(desktop_tests) != len(page_tests):
        differences.append("tests: desktop %d, page %d" % (len(desktop_tests), len(page_tests)))
    for mine, theirs in zip(desktop_tests, page_tests):
        for field in TEST_FIELDS:
            a, b = mine.get(field), theirs.get(field)
            if field == "output":
                a, b = without_picture(a or ""), without_picture(b or "")
            if a != b:
                differences.append("test %s %s: desktop %r, page %r" % (mine.get("number"), field, a, b))
    for kind in needs:
        if kind == "time-limit":
            found = any("s (time limit)" in (t.get("output") or "") for t in desktop_tests)
        else:
            found = any(t.get("status") == kind for t in desktop_tests)
        if not found:
            differences.append("the desktop's report has no test of the kind %s" % kind)
    for line in differences:
        print("compare_check_results: " + line)
    if differences:
        return 1
    print("compare_check_results: the same verdict: score %s of %s, %d tests, every message word for word" %
          (desktop.get("score"), desktop.get("max_score"), len(desktop_tests)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
