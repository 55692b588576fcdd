#!/bin/bash
# The share of a run's images in its second half (a loop's second lap: after
# the first pass through every room) that yield a measurement the pre-filter
# accepts, and the accepted measurements beyond 3 sigma of the truth.
#
#   scripts/second_half_measurements.sh ACCURACY_CSV GROUND_TRUTH.tum IMAGES
#
# ACCURACY_CSV: `vslam-frontend RAWLOG OUT --config INI --ground-truth TRUTH
# --accuracy-csv F`; IMAGES: the image count it prints. The second half is
# by time, between the ground truth's first and last stamps.
set -euo pipefail
[[ $# -eq 3 ]] || { sed -n '2,/^set -euo/p' "$0" | grep '^#' | sed 's/^# \{0,1\}//'; exit 1; }
CSV=$1 TRUTH=$2 IMAGES=$3
for f in "$CSV" "$TRUTH"; do [[ -r $f ]] || { echo "error: cannot read '$f'" >&2; exit 3; }; done
MID=$(awk '!/^#/ && NF >= 8 { if (first == "") first = $1; last = $1 } END { if (first == "") exit 1; printf "%.6f", (first + last) / 2 }' "$TRUTH") ||
	{ echo "error: '$TRUTH' holds no pose" >&2; exit 3; }
awk -F, -v mid="$MID" -v images="$IMAGES" '
NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i
          if (!("accepted" in col) || !("beyond_3_sigma" in col)) { print "error: not an accuracy CSV" > "/dev/stderr"; exit 3 }
          next }
$col["accepted"] == 1 {
	accepted++; beyond += $col["beyond_3_sigma"]; beyondOwn += $col["beyond_3_sigma_of_its_noise"]
	if ($1 >= mid && !($1 in seen)) { seen[$1] = 1; secondHalf++ }
}
END {
	printf "second half: %.0f%% of the images yield an accepted measurement (%d of %d)\n", 100 * secondHalf / (images / 2), secondHalf, images / 2
	printf "accepted measurements beyond 3 sigma of Sigma_vis: %d of %d (%.1f%%); of the noise the filter gives each: %d\n", beyond, accepted, accepted ? 100 * beyond / accepted : 0, beyondOwn
}' "$CSV"
