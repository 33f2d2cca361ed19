#!/bin/sh
# Regenerates the committed sample tables (nprlib/obscurance/tables/*.inc) with vo_samples:
# lines 5 and 9, points 12 and 33, by every method, and their neighbours (lines 4, 6, 8, 10,
# points 11, 13, 32, 34) electrostatic, at the default (full) resolution, 30 restarts and seed
# 1. Takes minutes; run it niced. Usage: regenerate_tables.sh PATH/TO/vo_samples
set -eu
tool=${1:?usage: regenerate_tables.sh PATH/TO/vo_samples}
tables=$(dirname "$0")/../tables
for method in electrostatic lloyd poisson; do
    for count in 5 9; do
        "$tool" --method $method --kind lines --count $count --format cpp \
            --output "$tables/${method}_lines_$count.inc"
    done
    for count in 12 33; do
        "$tool" --method $method --kind points --count $count --format cpp \
            --output "$tables/${method}_points_$count.inc"
    done
done
for count in 4 6 8 10; do
    "$tool" --method electrostatic --kind lines --count $count --format cpp \
        --output "$tables/electrostatic_lines_$count.inc"
done
for count in 11 13 32 34; do
    "$tool" --method electrostatic --kind points --count $count --format cpp \
        --output "$tables/electrostatic_points_$count.inc"
done
