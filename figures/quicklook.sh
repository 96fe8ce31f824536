#!/bin/sh
# Render a `springblock run --series FILE` TSV with gnuplot, no Python needed:
#   quicklook.sh SERIES.tsv [png|dumb]
# png writes SERIES.png beside the input; dumb draws in the terminal.
set -eu
if [ $# -lt 1 ] || [ ! -f "$1" ]; then
    echo "usage: $0 SERIES.tsv [png|dumb]" >&2
    exit 2
fi
file=$1
term=${2:-png}
case $term in
    png) out="${file%.tsv}.png" ;;
    dumb) out="" ;;
    *) echo "$0: terminal must be png or dumb, got '$term'" >&2; exit 2 ;;
esac
here=$(dirname "$0")
gnuplot -e "file='$file'; out='$out'; term='$term'" "$here/quicklook.gp"
[ -n "$out" ] && echo "$out"
exit 0
