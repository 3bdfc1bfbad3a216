#!/usr/bin/env bash
# docs/img/ltc_distance.png: each texel's distance (TV) of brdfbake's 64^2 GGX + smith-correlated fit
# and of the published 2016 table (three.js's copy), measured the same way, side by side.
#   tools/ltc_figure.sh [BUILD_DIR]     (needs the tests built, libjs-three and gnuplot)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
data=$(mktemp /tmp/ltc_distance.XXXXXX)
trap 'rm -f "$data"' EXIT
BRDFBAKE_LTC_DUMP="$data" "$build/tests/brdfbake-ltc-tests" --gtest_filter='Ltc.DefaultFitIsNoFartherThanThePublished2016Table'
gnuplot <<GP
set terminal pngcairo size 1100,480 font ",11"
set output "docs/img/ltc_distance.png"
set multiplot layout 1,2 title "LTC fit distance (total variation) per texel, ggx + smith-correlated, 64 x 64"
set xlabel "roughness r"; set ylabel "sqrt(1 - mu)"
set xrange [0:1]; set yrange [0:1]; set cbrange [0:0.5]
set palette defined (0 "#ffffff", 0.02 "#c6dbef", 0.1 "#6baed6", 0.25 "#2171b5", 0.5 "#08306b")
set view map
set title "brdfbake (mean 0.036)"
splot "$data" using 3:(sqrt(1-\$4)):5 with image notitle
set title "published 2016 fit (mean 0.062)"
splot "$data" using 3:(sqrt(1-\$4)):6 with image notitle
unset multiplot
GP
echo "wrote docs/img/ltc_distance.png"
