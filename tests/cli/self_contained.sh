#!/usr/bin/env bash
# Self-contained run folders and studies (issue 48).
#  - Every shipped scene (scenes/*.cfg) and study base (studies/*_base.cfg,
#    load only): the run folder's scene.cfg loads
#    back and, run for the same steps, gives the same state bit for bit
#    (tools/checkpoint_state_diff.py: every dataset and attribute but the
#    embedded scene text, which names the folder's own file copies).
#  - A scene that reads a pair table and an init file: both copied into the
#    run folder and named by its scene.cfg, which loads from a copy of the
#    folder elsewhere after the originals are gone, and restarts from it
#    (10 == 5 + restart + 5); a changed table is refused on restart.
#  - Resume in place refuses (exit 2, one line, nothing changed) when an
#    output it appends to is missing: colloids.h5, colloids.xyz, thermo.tsv.
#  - A study of that scene: its points find both files (they are named
#    relative to the base scene's folder), run, and their folders hold
#    copies.
set -u
PELOID=$(realpath "${1:-bin/peloid}")
ROOT=$(realpath "$(dirname "$0")/../..")
PY=/usr/bin/python3
T=$(mktemp -d /tmp/peloid-self.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }
STEPS=4

echo "== self-contained run folders: scene.cfg of every shipped scene loads back and reproduces the run"
for s in "$ROOT"/scenes/*.cfg; do
  n=$(basename "$s" .cfg)
  if ! "$PELOID" run "$s" --out "a_$n" --steps $STEPS --threads 2 > /dev/null 2> err.txt; then
    bad "$n: the run failed: $(tail -1 err.txt)"; continue
  fi
  if ! "$PELOID" run "a_$n/scene.cfg" --out "b_$n" --steps $STEPS --threads 2 > /dev/null 2> err.txt; then
    bad "$n: its scene.cfg does not load back: $(grep -m1 error err.txt)"; continue
  fi
  if $PY "$ROOT/tools/checkpoint_state_diff.py" "a_$n/checkpoint.h5" "b_$n/checkpoint.h5" > diff.txt 2>&1; then
    ok "$n: scene.cfg reproduces the run ($STEPS steps, state bitwise)"
  else
    bad "$n: scene.cfg's run differs: $(head -3 diff.txt | tr '\n' ' ')"
  fi
done

echo "== the studies' base scenes: scene.cfg of a run loads back"
for s in "$ROOT"/studies/*_base.cfg; do
  n=$(basename "$s" .cfg)
  "$PELOID" run "$s" --out "s_$n" --steps 0 --threads 1 > /dev/null 2> err.txt || { bad "$n: $(tail -1 err.txt)"; continue; }
  "$PELOID" check "s_$n/scene.cfg" > /dev/null 2> err.txt && ok "$n: scene.cfg loads back" || bad "$n: $(head -1 err.txt)"
done

echo "== a scene that reads a table and an init file, and a study of it"
mkdir -p src/sub
$PY - <<'PYEOF'
import math
# a soft repulsion U = 3 (1 - r/8)^2 on r in [3.9, 8] (a0), F = -dU/dr
with open("src/sub/soft.table", "w") as f:
    f.write("# soft repulsion\n")
    n = 200
    for i in range(n):
        r = 3.9 + (8.0 - 3.9) * i / (n - 1)
        f.write("%.10f %.12g %.12g\n" % (r, 3.0 * (1 - r / 8.0) ** 2, 6.0 / 8.0 * (1 - r / 8.0)))
with open("src/sub/pos.txt", "w") as f:
    f.write("# x y z\n")
    for k in range(8):
        f.write("%g %g %g\n" % (4 + 8 * (k & 1), 4 + 8 * ((k >> 1) & 1), 4 + 8 * ((k >> 2) & 1)))
PYEOF
cat > src/sub/tab.cfg <<'CFG'
name = "tab";
seed = 3;
steps = 10;
box: { cells = [16, 16, 16]; };
fluid: { density = 3.0; };
colloids: { count = 8; radius = 2.0; pairs = "table"; table_file = "soft.table";
            init = "file"; init_file = "pos.txt"; substeps = 4; };
coupling: { method = "hecht2"; };
output: { thermo_interval = 5; checkpoint_interval = 5; };
CFG
"$PELOID" run src/sub/tab.cfg --out full --threads 1 > /dev/null 2> err.txt || bad "table scene: $(tail -1 err.txt)"
if [ -f full/pair_table.txt ] && [ -f full/colloids_init.txt ] && cmp -s full/pair_table.txt src/sub/soft.table \
   && grep -q '^  table_file = "pair_table.txt";' full/scene.cfg && grep -q '^  init_file = "colloids_init.txt";' full/scene.cfg; then
  ok "the run folder holds pair_table.txt and colloids_init.txt, and its scene.cfg names them"
else
  bad "run folder copies: $(ls full | tr '\n' ' ')"
fi
# the folder elsewhere, the originals gone
cp -r full moved; mv src src_gone
"$PELOID" run moved/scene.cfg --out again --threads 2 > /dev/null 2> err.txt \
  && $PY "$ROOT/tools/checkpoint_state_diff.py" full/checkpoint.h5 again/checkpoint.h5 > /dev/null \
  && ok "a copy of the folder runs from its scene.cfg alone: the same state" || bad "moved folder: $(tail -1 err.txt)"
"$PELOID" run moved/scene.cfg --out half --steps 5 --threads 1 > /dev/null 2>&1
"$PELOID" run moved/scene.cfg --out half --restart half/checkpoint.h5 --steps 5 --threads 2 > /dev/null 2> err.txt \
  && $PY "$ROOT/tools/checkpoint_state_diff.py" full/checkpoint.h5 half/checkpoint.h5 > /dev/null \
  && ok "restart from the folder's scene.cfg: 10 == 5 + restart + 5" || bad "restart from the folder: $(tail -1 err.txt)"
cp -r moved changed
$PY -c "
import sys
rows = [l.split() for l in open('changed/pair_table.txt') if not l.startswith('#')]
with open('changed/pair_table.txt', 'w') as f:
    for r, u, fo in rows: f.write('%s %.12g %.12g\\n' % (r, 1.1 * float(u), 1.1 * float(fo)))
"
"$PELOID" run changed/scene.cfg --out changed --restart changed/checkpoint.h5 --steps 5 > /dev/null 2> err.txt; rc=$?
[ $rc -eq 2 ] && grep -q "colloids.table_file" err.txt && ok "a changed table is refused on restart: $(head -c 160 err.txt)" \
  || bad "changed table on restart: rc $rc $(cat err.txt)"
mv src_gone src
cat > src/study.cfg <<'CFG'
name = "tabstudy";
scene = "sub/tab.cfg";
out = "study_out";
grid = ( { key = "seed"; values = [1, 2]; } );
CFG
"$PELOID" sweep src/study.cfg --jobs 1 --threads 1 > sweep.txt 2>&1; rc=$?
ls study_out/scenes/soft.table study_out/scenes/pos.txt > /dev/null 2>&1 && ok "the study's scenes/ folder holds the files its points read" \
  || bad "study scenes/: $(ls study_out/scenes | tr '\n' ' ')"
nt=$(ls study_out/*/pair_table.txt 2>/dev/null | wc -l)
[ $rc -eq 0 ] && [ "$nt" -eq 2 ] && ok "a study of the scene finds its table and init file: 2 points ran, each folder holds its copies" \
  || bad "study: rc $rc, $nt table copies: $(tail -2 sweep.txt | tr '\n' ' ')"

echo "== resume in place checks every output it appends to"
printf 'name = "rs";\nseed = 4;\nsteps = 20;\nbox: { cells = [12, 12, 12]; };\nfluid: { density = 3.0; };\ncolloids: { count = 4; radius = 1.5; pairs = "hertz"; trajectory_interval = 2; substeps = 2; };\ncoupling: { method = "hecht2"; };\noutput: { thermo_interval = 2; checkpoint_interval = 10; colloids_xyz = true; };\n' > rs.cfg
for gone in colloids.h5 colloids.xyz thermo.tsv; do
  rm -rf rs_$gone
  "$PELOID" run rs.cfg --out rs_$gone --steps 10 --threads 1 > /dev/null 2>&1
  rm -f rs_$gone/$gone
  cp rs_$gone/checkpoint.h5 before.h5
  "$PELOID" run rs.cfg --out rs_$gone --restart rs_$gone/checkpoint.h5 --steps 10 > /dev/null 2> err.txt; rc=$?
  if [ $rc -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q "rs_$gone/$gone: missing" err.txt \
     && [ ! -e rs_$gone/$gone ] && cmp -s before.h5 rs_$gone/checkpoint.h5; then
    ok "resume in place without $gone refused, nothing written: $(cat err.txt)"
  else
    bad "resume in place without $gone: rc $rc, $(cat err.txt)"
  fi
done
"$PELOID" run rs.cfg --out rs_ok --steps 10 --threads 1 > /dev/null 2>&1
"$PELOID" run rs.cfg --out rs_ok --restart rs_ok/checkpoint.h5 --steps 10 > /dev/null 2> err.txt \
  && [ "$(grep -vc '^step' rs_ok/thermo.tsv)" -eq 11 ] && ok "resume in place with every output: 11 thermo rows" \
  || bad "resume in place: $(tail -1 err.txt)"

echo "self_contained: $pass passed, $fail failed"
[ $fail -eq 0 ]
