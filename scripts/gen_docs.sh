#!/usr/bin/env bash
# Makes the documentation's pictures and screens again with the program itself.
# Run from the repository root:
#   scripts/gen_docs.sh          the screens and outputs, then every picture
#   scripts/gen_docs.sh screens  only the screens and outputs (seconds)
# The screens and outputs are the blocks under a `<!-- screen: … -->` or
# `<!-- output: … -->` marker in README.md and docs/*.md, and the class
# pictures of docs/teaching.md; tests/docs_blocks.rs checks them and, with
# ROUGHTUI_UPDATE_DOCS=1, writes them.
set -euo pipefail
ROUGHTUI_UPDATE_DOCS=1 cargo test --quiet --test docs_blocks
if [ "${1:-}" = screens ]; then
    exit 0
fi
cargo build --release --quiet
bin=target/release/roughtui
for view in slopes indices map load; do
    "$bin" export --preset fig2 --view "$view" --format svg > "docs/fig2-$view.svg"
done
"$bin" export --preset fig3 --view map --format svg > docs/fig3-map.svg
"$bin" export --preset fig4 --view map --format svg > docs/fig4-map.svg
# The example surface (surfaces/example.txt, a Gwyddion-style height map):
# its spectrum and its indices.
for view in spectrum indices; do
    "$bin" export --surface surfaces/example.txt --view "$view" --format svg \
        > "docs/example-$view.svg"
done
# The example surface's moments, one panel a quantity.
"$bin" export --surface surfaces/example.txt --view moments --format svg \
    > docs/example-moments.svg
# The contact simulation beside the theory (docs/theory-vs-simulation.md):
# small grids, so that the pictures take seconds, not minutes.
"$bin" export --preset fig2 --set zeta=32 --view contact-map --format svg \
    > docs/fig2-contact-map.svg
"$bin" export --preset fig4 --set zeta=32 --view contact --format svg \
    > docs/fig4-contact.svg
"$bin" export --preset fig2 --view contact-sweep --format svg > docs/fig2-contact-sweep.svg
# The paper's figure with the simulation's initial slopes (fig2, four seeds
# in a cell of one longest wavelength: about two minutes), and the
# elastic-again scene's, four seeds in a cell of two (about six minutes).
"$bin" export --preset fig2 --view contact-slopes --cell 1 --seeds 4 --format svg \
    > docs/fig2-contact-slopes.svg
"$bin" export --preset elastic-again --view contact-slopes --cell 2 --seeds 4 --format svg \
    > docs/elastic-again-contact-slopes.svg
echo "wrote docs/*.svg" >&2
