"""How many tests a ctest run skipped, and why (scripts/test.sh prints it after each ctest run).

    /usr/bin/python3 scripts/skipped_tests.py RESULTS.xml

RESULTS.xml is what `ctest --output-junit` writes, with every test's output (scripts/test.sh raises
ctest's output limit so that nothing is cut). Counted, each with its reason:
- ctest tests that did not run: Google Test's GTEST_SKIP (its message) and scripts that exit with 77
  (their lines "SKIPPED reason");
- pytest's skipped tests, inside the ctest tests python.module.* (pytest runs with -rs, which lists
  "SKIPPED [count] place: reason");
- parts that a script skipped in a test that ran (its "SKIPPED reason" lines).
Equal reasons are counted together."""
import collections
import re
import sys
import xml.etree.ElementTree as ElementTree

PYTEST_SKIP = re.compile(r"^SKIPPED \[(\d+)\] [^:]+:\d+: (.*)$", re.MULTILINE)
SCRIPT_SKIP = re.compile(r"^SKIPPED:? (?!\[)(.*)$", re.MULTILINE)
GTEST_SKIP = re.compile(r": Skipped\n(.*?)\n?\[  SKIPPED \]", re.DOTALL)
PYTEST_TOTALS = re.compile(r"^=*\s*((?:\d+ \w+(?:, )?)+) in [\d.]+s", re.MULTILINE)
PYTEST_OUTCOMES = ("passed", "failed", "skipped", "error", "errors", "xfailed", "xpassed")


def why_not_run(case, output):
    """The reason a ctest test gives for not running."""
    gtest = GTEST_SKIP.search(output)
    if gtest:
        return gtest.group(1).strip().splitlines()[0] if gtest.group(1).strip() else "GTEST_SKIP without a message"
    lines = SCRIPT_SKIP.findall(output)
    return "; ".join(lines) if lines else case.find("skipped").get("message", "no reason given")


def pytest_total(output):
    """How many tests pytest ran (its last line: "12 passed, 2 skipped in 1.50s"), or 0."""
    totals = PYTEST_TOTALS.findall(output)
    if not totals:
        return 0
    return sum(int(count) for count, outcome in re.findall(r"(\d+) (\w+)", totals[-1]) if outcome in PYTEST_OUTCOMES)


def main(results_path):
    try:
        cases = ElementTree.parse(results_path).getroot().iter("testcase")
    except (ElementTree.ParseError, FileNotFoundError):
        print(f"skipped tests: ctest wrote no results ({results_path})")
        return
    reasons = collections.Counter()  # (kind, reason) -> count
    ctest_total = pytest_tests = 0
    for case in cases:
        ctest_total += 1
        output = case.findtext("system-out") or ""
        if case.find("skipped") is not None:
            reasons["ctest", why_not_run(case, output)] += 1
            continue
        pytest_tests += pytest_total(output)
        for count, reason in PYTEST_SKIP.findall(output):
            reasons["pytest", reason] += int(count)
        for reason in SCRIPT_SKIP.findall(output):
            reasons["part", reason] += 1
    count_of = collections.Counter()
    for (kind, _), count in reasons.items():
        count_of[kind] += count
    pytest = f"{count_of['pytest']} of {pytest_tests} pytest tests" if pytest_tests else "no pytest tests run"
    parts = f", {count_of['part']} part(s) of tests that ran" if count_of["part"] else ""
    print(f"skipped: {count_of['ctest']} of {ctest_total} ctest tests, {pytest}{parts}")
    for (kind, reason), count in sorted(reasons.items(), key=lambda item: (-item[1], item[0])):
        print(f"  {count:4d} {kind}: {reason}")


if __name__ == "__main__":
    main(sys.argv[1])
