#!/usr/bin/env bash
# Regenerates the README's pictures in docs/ with the program itself.
# Run from the repository root: scripts/gen_docs.sh
set -euo pipefail
cargo build --release --quiet
bin=target/release/roughtui
for view in slopes indices map load; do
    "$bin" export --preset fig2 --view "$view" --format svg > "docs/fig2-$view.svg"
done
"$bin" export --preset fig3 --view map --format svg > docs/fig3-map.svg
"$bin" export --preset fig4 --view map --format svg > docs/fig4-map.svg
# A measured-surface example: an isotropic PSD table (SurfaceTopography's
# C^iso, m⁴) of fig2's power law rolled off below q_r = 1e5 /m,
# C = (2π)² Z q_r^(−2(1+H)) / (1 + (q/q_r)²)^(1+H), Z = 1e-8, H = 0.8,
# ten points per decade from 1e4 to 1e9 /m.
awk 'BEGIN {
    pi = atan2(0, -1); z = 1e-8; h = 0.8; qr = 1e5
    print "# fig2 power law with a roll-off knee at q_r = 1e5 /m (scripts/gen_docs.sh)"
    print "# q (1/m)  C^iso (m^4), SurfaceTopography convention"
    for (i = 0; i <= 50; i++) {
        q = 1e4 * 10 ^ (i / 10)
        c = (2 * pi) ^ 2 * z * qr ^ (-2 * (1 + h)) / (1 + (q / qr) ^ 2) ^ (1 + h)
        printf "%.17g %.17g\n", q, c
    }
}' > docs/knee-psd.txt
for view in spectrum indices; do
    "$bin" export --surface docs/knee-psd.txt --set zeta=1000 --view "$view" --format svg \
        > "docs/knee-$view.svg"
done
echo "wrote docs/*.svg" >&2
