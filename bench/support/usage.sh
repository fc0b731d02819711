# Sourced by the bench scripts right after `set -euo pipefail`: with -h or --help as the first
# argument, prints the script's header comment (its usage) and exits 0, before the script reads
# or writes anything.
if [[ ${1:-} == -h || ${1:-} == --help ]]; then
  sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'
  exit 0
fi
