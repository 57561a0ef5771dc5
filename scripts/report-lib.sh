# Helpers shared by the scripts that regenerate doc/ results (sourced).
# json FILE EXPR: prints the Python expression EXPR over the JSON document d.
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }
# median V...: the median of the numbers.
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
# A scratch directory, removed on exit: $work.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
