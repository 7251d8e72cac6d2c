# Sourced by the bench scripts: `alternate RUNS "label::command args" ...` runs every command
# once per round, RUNS rounds (so that a change in the machine's load hits them alike), and
# prints each label's medians of wall time, CPU time (user + system) and peak RSS from
# /usr/bin/time. Commands are split on spaces (no quoting inside them).
alternate() {
    local runs=$1
    shift
    local log
    log=$(mktemp)
    for _ in $(seq "$runs"); do
        for c in "$@"; do
            # shellcheck disable=SC2086 # the command is split into its words on purpose
            /usr/bin/time -f "${c%%::*} %e %U %S %M" -a -o "$log" ${c#*::} >/dev/null 2>&1 ||
                echo "${c%%::*}: failed" >&2
        done
    done
    python3 - "$log" <<'PY'
import statistics as s, sys
rows = {}
for line in open(sys.argv[1]):
    label, wall, user, system, rss = line.split()
    rows.setdefault(label, []).append((float(wall), float(user) + float(system), int(rss)))
for label, r in rows.items():
    wall = s.median(x[0] for x in r)
    cpu = s.median(x[1] for x in r)
    rss = s.median(x[2] for x in r) / 1024
    print(f"{label}: wall {wall:.3f} s, CPU {cpu:.3f} s, peak RSS {rss:.0f} MiB (medians of {len(r)})")
PY
    rm -f "$log"
}
