# Sourced by accuracy_variants.sh and door_gaps.sh (on the lent GPU machine), with $lumina set.

# figures REF TEST: relMSE and mean radiance (R, G, B averaged) of TEST over REF's, as "relmse ratio".
figures() {
  $lumina compare "$1" "$2" 2>&1 | awk '
    /^  relMSE/ { r = $2 }
    /^  mean / { gsub(/[(),]/, " "); ref = ($3 + $4 + $5) / 3; test = ($7 + $8 + $9) / 3 }
    END { printf "%s %.4f\n", r, test / ref }'
}
