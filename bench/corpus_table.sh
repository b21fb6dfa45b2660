#!/usr/bin/env bash
# The corpus table of docs/CORPUS.md: runs the corpus test (tests/gl/CorpusTest.cpp, one CTest
# test per model of Debian's inventor-data), then measures each model's GL picture against its
# reference with `ivshadow compare --json` and writes the table, with the summary above it,
# into docs/CORPUS.md between its "corpus table" markers (and prints it). Failing models are
# listed too: the table is what the build renders today, whatever the floors say.
# Run after ./run build (inventor-data installed); BUILD_DIR as for ./run.
#   bench/corpus_table.sh
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
start=$(date +%s.%N)
ctest --test-dir "$build" -R '^(InventorData|Corpus)[.]' -j "$(nproc)" >"$build/corpus_ctest.log" 2>&1 ||
  echo "some corpus tests failed: $build/corpus_ctest.log" >&2
end=$(date +%s.%N)
for dir in "$build"/test-output/InventorData.*/; do
  if [ -f "$dir/gl.png" ] && [ -f "$dir/reference.png" ]; then
    "$build/bin/ivshadow" compare "$dir/reference.png" "$dir/gl.png" --json "$dir/compare.json" \
      >/dev/null
  else
    rm -f "$dir/compare.json"
  fi
done
table=$(python3 - "$build" "$(python3 -c "print(round($end - $start))")" <<'PY'
import glob, json, os, statistics, sys
build, seconds = sys.argv[1], sys.argv[2]
rows = []
for result in glob.glob(os.path.join(build, "test-output", "InventorData.*", "result.txt")):
    fields = dict(line.split(" ", 1) for line in open(result).read().splitlines() if " " in line)
    compare = os.path.join(os.path.dirname(result), "compare.json")
    metrics = json.load(open(compare))["all"] if os.path.exists(compare) else None
    psnr = None if metrics is None else metrics["psnr_db"]
    rows.append((fields, metrics, psnr))
# Worst first; identical pictures (PSNR infinite) last; models without pictures first of all.
def key(row):
    fields, metrics, psnr = row
    return (metrics is not None, float("inf") if psnr is None else psnr, fields["model"])
rows.sort(key=key)
finite = [psnr for _, metrics, psnr in rows if metrics is not None and psnr is not None]
compared = [row for row in rows if row[1] is not None]
identical = sum(1 for _, metrics, psnr in compared if psnr is None)
unreadable = [f["model"] for f, metrics, _ in rows if "unreadable" in f]
everything = [psnr if psnr is not None else float("inf") for _, _, psnr in compared]
print("%d models: %d rendered and compared, %d identical to the reference, %d that Coin cannot "
      "read (exit 2 from both commands); median PSNR %s dB, worst %.1f dB; the corpus test took "
      "%s s with `ctest -j %d`." % (
          len(rows), len(compared), identical, len(unreadable),
          "%.1f" % statistics.median(everything) if statistics.median(everything) != float("inf")
          else "inf", min(finite) if finite else float("inf"), seconds, os.cpu_count()))
print()
print("| model | render exit | reference exit | PSNR dB | max error | > 2/255 | render s | reference s |")
print("|---|---|---|---|---|---|---|---|")
for fields, metrics, psnr in rows:
    if metrics is None:
        print("| %s | %s | %s | — | — | — | — | — |" % (
            fields["model"], fields.get("render_exit", "—"), fields.get("reference_exit", "—")))
        continue
    print("| %s | %s | %s | %s | %d | %.2f %% | %.2f | %.2f |" % (
        fields["model"], fields["render_exit"], fields["reference_exit"],
        "identical" if psnr is None else "%.1f" % psnr, metrics["max_abs_error"],
        100.0 * metrics["share_above_2"], float(fields["render_s"]),
        float(fields["reference_s"])))
PY
)
echo "$table"
python3 - "$table" <<'PY'
import re, sys
path = "docs/CORPUS.md"
text = open(path).read()
new = re.sub(r"(<!-- corpus table -->\n).*?(<!-- /corpus table -->)",
             lambda m: m.group(1) + sys.argv[1] + "\n" + m.group(2), text, flags=re.S)
open(path, "w").write(new)
PY
