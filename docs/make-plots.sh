#!/usr/bin/env bash
# Regenerates the lobe plots in docs/plots/ from the CLI (Release build), offscreen.
set -euo pipefail
cd "$(dirname "$0")/.."
cli=build/release/app/millexpert-cli
plot=build/release/app/gui/millexpert-plot
out=docs/plots
tmp=$(mktemp -d)
mkdir -p "$out"
export QT_QPA_PLATFORM=offscreen
p=projects/benchmark-insperger-1dof.mxproj
for tool in FULL LOW; do
  for method in zoa sdm; do
    "$cli" lobes "$p" --tool "$tool" --method "$method" --from 5000 --to 25000 --step 50 --delta 0 --alpha 1 \
      --max-depth 10 > "$tmp/$tool-$method.json"
  done
  "$cli" lobes "$p" --tool "$tool" --method sdm --from 5000 --to 25000 --step 50 --delta 50 --alpha 1 \
    --max-depth 10 > "$tmp/$tool-sdm-delta50.json"
done
"$plot" "$out/insperger-full-immersion.png" --title "Insperger benchmark, a/D = 1, 2 teeth, down milling" \
  --max-depth 5 "$tmp/FULL-zoa.json=ZOA (delta = 0)" "$tmp/FULL-sdm.json=SDM m = 40 (delta = 0)" \
  "$tmp/FULL-sdm-delta50.json=SDM m = 40, delta = 50 1/s"
"$plot" "$out/insperger-low-immersion.png" --title "Insperger benchmark, a/D = 0.05, 2 teeth, down milling" \
  --max-depth 10 "$tmp/LOW-zoa.json=ZOA (delta = 0)" "$tmp/LOW-sdm.json=SDM m = 40 (delta = 0)" \
  "$tmp/LOW-sdm-delta50.json=SDM m = 40, delta = 50 1/s"
p=projects/rubio2006-tool-selection.mxproj
for tool in R1 R2; do
  "$cli" lobes "$p" --tool "$tool" --method zoa --from 1000 --to 12000 --step 10 --delta 0 --alpha 1 > "$tmp/$tool-zoa.json"
  "$cli" lobes "$p" --tool "$tool" --method sdm --from 1000 --to 12000 --step 50 --delta 0 --alpha 1 > "$tmp/$tool-sdm.json"
done
"$plot" "$out/rubio2006-r1-r2.png" --title "Rubio et al. 2006: tools R1 and R2, full-immersion up milling" \
  --max-depth 2.5 "$tmp/R1-zoa.json=R1 ZOA" "$tmp/R1-sdm.json=R1 SDM m = 40" "$tmp/R2-zoa.json=R2 ZOA" \
  "$tmp/R2-sdm.json=R2 SDM m = 40"
# Figures 9-12 (closed loop for beta = -0.3, 0, 0.3, 1) and figure 13 (J_c against beta).
p=projects/rubio2006-adaptive-control.mxproj
for b in -0.3 0 0.3 1; do
  name=$(echo "$b" | sed 's/^-/m/')
  "$plot" "$out/control-beta-$name.png" --control "$p" --beta="$b"
done
"$plot" "$out/control-jc.png" --control "$p" --jc=-1:1:0.02
# The beta-FROH study: J_c(beta) for T/16, T/8 (default), T/6 (threshold -0.6), 19 ms (the reference-model
# reading's isolated dip at -0.35), T/2 and T (T = 60/715 s), both readings of eq. 34.
"$cli" control "$p" --beta-study --tau-c-ms 5.2448,10.4895,13.9860,19,41.958,83.916 --sweep-beta=-1:1:0.05 \
  > "$tmp/beta-study.json"
"$plot" "$out/control-beta-study.png" --beta-study "$tmp/beta-study.json"
rm -rf "$tmp"
echo "plots written to $out/"
