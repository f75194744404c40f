#!/usr/bin/env bash
# study_test.sh NCSIM: `ncsim study` on this machine (issue 37 step 5, docs/study.md): a bad
# study file is refused with every error positioned (exit 2), an axis the base cannot vary is
# NC7206 at the axis; `run --jobs 1` and `--jobs 2` and jobs run one by one in reverse order
# with `job` + `merge` give byte-identical tables; a missing result (NC7209), a study changed
# since the plan (NC7207) and a job outside the study (NC7208) are refused.
set -uo pipefail
ncsim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/expect.sh"
cp -r "$here/study" "$work/study"
# The studies' paths are relative to their folder: made absolute in the copy.
sed -i -e "s#\"\.\./\.\./\.\./#\"$(cd "$here/../.." && pwd)/#" -e "s#\"\.\./#\"$here/#" "$work"/study/*.toml
st=$work/study

expect "a bad study file: every error positioned, exit 2" 2 '' \
  'bad_file.toml:3:23: error: vary.belt_velocity\[2\] = -1 mm/s is out of range.*\[NC7004\]' \
  -- study plan "$st/bad_file.toml" -o "$work/bad"
holds "a bad study file: nothing is planned" test ! -e "$work/bad/jobs.csv"
expect "an axis the base cannot vary is NC7206 at the axis" 2 '' \
  'bad_axis.toml:4:1: error: vary.fluctuation: .*\[NC7206\]' \
  -- study plan "$st/bad_axis.toml" -o "$work/bad"
again "... and the other axis too, in the same pass" 2 '' 'bad_axis.toml:5:1: error: vary.seed: .*\[NC7206\]'
sed 's/-1/90/' "$st/bad_file.toml" >"$st/bad_program.toml"
expect "a program that does not exist is NC7205 at its value" 2 '' \
  "bad_program.toml:1:11: error: no such program: .*\[NC7205\]" \
  -- study plan "$st/bad_program.toml" -o "$work/bad"

# The program base: 3 belt velocities x 2 spacings.
expect "plan: the job list and the batch script" 0 '^study: 6 jobs planned in .* \(jobs.csv, study.sbatch: 6 array tasks\)$' '' \
  -- study plan "$st/squares.toml" -o "$work/sq"
holds "plan: the job list has one row per job, the last axis fastest" bash -c "
  [[ \$(sed -n '5,7p' '$work/sq/jobs.csv') == \$'job,belt_velocity_mm_s,pitch_mm\n0,80,600\n1,80,700' ]]"
holds "plan: the batch script is a job array over the jobs" grep -q '^#SBATCH --array=0-5$' "$work/sq/study.sbatch"
expect "run --jobs 2: every job, one table" 0 '^study: 6 rows merged into .*/sq/results.csv$' '' \
  -- study run "$st/squares.toml" -o "$work/sq" --jobs 2
holds "run: the table's header, one row per job in job order" bash -c "
  head -1 '$work/sq/results.csv' | grep -qx 'job,belt_velocity_mm_s,pitch_mm,exit,stop,error_id,end_s,arrived,taken,missed,per_minute,audit,audit_violations,error' &&
  [[ \$(tail -n +2 '$work/sq/results.csv' | cut -d, -f1 | tr '\n' ' ') == '0 1 2 3 4 5 ' ]]"
holds "run: every sheet cut, audit clean, at every velocity and spacing" bash -c "
  [[ \$(tail -n +2 '$work/sq/results.csv' | cut -d, -f4,5,9,12 | sort -u) == '0,program end,3,ok' ]]"
holds "run: a faster belt and a closer spacing end sooner" python3 -c "
import csv
r = {(row['belt_velocity_mm_s'], row['pitch_mm']): float(row['end_s']) for row in csv.DictReader(open('$work/sq/results.csv'))}
assert r[('120', '600')] < r[('80', '600')] and r[('80', '600')] < r[('80', '700')], r"
expect "run --jobs 1: the same table" 0 '' '' -- study run "$st/squares.toml" -o "$work/sq1" --jobs 1
same "run --jobs 1 and --jobs 2 give byte-identical tables" "$work/sq/results.csv" "$work/sq1/results.csv"

# A fluctuation axis on a program base, and programs varied: failures are rows, not failures.
expect "vary.fluctuation: the study runs" 0 '^study: 2 rows merged' '' \
  -- study run "$st/fluctuation.toml" -o "$work/fl"
holds "vary.fluctuation: clean without fluctuation, the belt's jerk a violation at 5 % (exit 3)" bash -c "
  [[ \$(cut -d, -f1-4,11,12 '$work/fl/results.csv' | tail -n +2) == \$'0,0,0,program end,ok,0\n1,5,3,program end,violated,2449' ]]"
expect "vary.program: a job that ends in a run-time error is a row of the table" 0 '^study: 2 rows merged' '' \
  -- study run "$st/programs.toml" -o "$work/pr"
holds "vary.program: the error's id, stop and positioned first line in its row" bash -c "
  tail -n 1 '$work/pr/results.csv' | grep -Eq '^1,/[^,]*/programs/belt_too_fast/belt_too_fast.nc,1,error,50653,[0-9.]+,,0,,0,violated,[0-9]+,\"/.*/belt_too_fast.nc:15:1: error: run-time error at t=5.346 s: .*\\[50653\\]\"\$'"
sed 's#belt_too_fast/belt_too_fast.nc"#../tests/cli/two_errors.nc"#' "$st/programs.toml" >"$st/syntax.toml"
expect "a program of the study with syntax errors is refused at the plan, positioned" 2 '' \
  'two_errors.nc:3:1: error: unexpected \$ENDIF \[20218\]' -- study plan "$st/syntax.toml" -o "$work/sy"

# The line base, job by job in reverse order, then merged.
expect "plan a line study" 0 '^study: 6 jobs planned' '' -- study plan "$st/pickers.toml" -o "$work/pk"
expect "merge before the jobs ran: every missing job named" 2 '' \
  '6 of 6 jobs have no result .*: jobs 0 1 2 3 4 5 .*\[NC7209\]' -- study merge "$work/pk"
for i in 5 4 3 2 1 0; do
  "$ncsim" study job "$work/pk" $i || echo "FAIL study job $i: exit $?"
done
expect "merge: the rows in job order" 0 '^study: 6 rows merged' '' -- study merge "$work/pk"
expect "run --jobs 2 of the same study" 0 '' '' -- study run "$st/pickers.toml" -o "$work/pk2" --jobs 2
same "jobs one by one in reverse order and run --jobs 2: byte-identical tables" \
  "$work/pk/results.csv" "$work/pk2/results.csv"
holds "line study: nothing lost in any job (arrived = taken + missed)" python3 -c "
import csv
rows = list(csv.DictReader(open('$work/pk/results.csv')))
assert len(rows) == 6
for r in rows:
    assert r['exit'] == '0' and r['audit'] == 'ok', r
    assert int(r['arrived']) == int(r['taken']) + int(r['missed']) and int(r['arrived']) == 40, r
assert len({r['end_s'] for r in rows}) > 1"
expect "merge -o -: the table on stdout" 0 '^job,belt_velocity_mm_s,seed,exit' '' -- study merge "$work/pk" -o -
expect "a job outside the study is NC7208" 2 '' 'job 6 is not in the study .*\[NC7208\]' -- study job "$work/pk" 6
expect "a negative job index is a usage error" 2 '' 'index: Value -1 not in range' -- study job "$work/pk" -1
expect "a folder that is no plan is NC7208" 2 '' 'not a planned study.*\[NC7208\]' -- study job "$work" 0
echo "# changed" >>"$st/pickers.toml"
expect "a study changed since its plan is NC7207" 2 '' 'changed since it was planned.*\[NC7207\]' -- study job "$work/pk" 0
sed -i '$d' "$st/pickers.toml"
rm "$work/pk/results/job-000003.csv"
expect "a missing result is NC7209, named" 2 '' '1 of 6 jobs have no result .*: jobs 3 .*\[NC7209\]' \
  -- study merge "$work/pk" -o "$work/never.csv"
holds "a merge that failed writes no table" test ! -e "$work/never.csv"
summary study_test
