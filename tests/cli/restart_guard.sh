#!/usr/bin/env bash
# Issue 18, checkpoint and guard side, through bin/peloid:
#  - a corrupted checkpoint is refused (exit 2, one line, nothing written):
#    NaN in fluid/x, a flipped exponent bit, x = 1e300 and -1e9, a step of
#    -7 and 2^63-3, a wrong checksum, an unknown format version, colloid
#    positions, image counters and MD step counters out of range (the value
#    cases rewrite the checksum, so that the range check itself is tested);
#  - a restart into a scene with another physics key is refused with the key
#    and both values (srd.dt, fluid.temperature, srd.rule, fluid.body_force,
#    thermostat.type, a walls checkpoint into a periodic scene), unless
#    --restart-changed names it; non-physics keys may change;
#  - the fluid guard stops runaway scenes with exit 3 and one line, and no
#    non-finite value reaches thermo.tsv (wall speed 1000, an absurd dt with
#    a body force, a temperature running away from the thermostat).
# On the code before issue 18 every case below was accepted (exit 0) or
# crashed (NaN / flipped bit: segfault in kernels/srd_stream.c).
set -u
PELOID=$(realpath "${1:-bin/peloid}")
PY=/usr/bin/python3
T=$(mktemp -d /tmp/peloid-ckpt.XXXXXX)
trap 'rm -rf "$T"' EXIT
cd "$T"
pass=0; fail=0
ok()  { pass=$((pass+1)); echo "  ok   $1"; }
bad() { fail=$((fail+1)); echo "  FAIL $1"; }

# scene TEXT_OVERRIDES...: the base scene with sed substitutions applied
BASE='name = "base";
seed = 5;
steps = 20;
box: { cells = [6, 6, 6]; walls_z = "WALLS"; };
fluid: { density = 5.0; temperature = 1.0; body_force = [0.0, 0.0, 0.0]; };
srd: { dt = 0.5; rule = "random_axis"; };
thermostat: { type = "heyes"; temperature = 1.0; };
output: { thermo_interval = 5; };
'
mk() { # mk FILE WALLS [sed-expr...]
  local f=$1 w=$2; shift 2
  local s=${BASE//WALLS/$w}
  printf '%s' "$s" > "$f"
  for e in "$@"; do sed -i "$e" "$f"; done
}

# refused NAME NEEDLE... (runs the command in $CMD): exit 2, one line, no out dir
refused() {
  local name=$1; shift
  "${CMD[@]}" --out "o_$name" 2> err.txt; local rc=$?
  local okk=1
  [ $rc -eq 2 ] || okk=0
  [ "$(wc -l < err.txt)" -eq 1 ] || okk=0
  for n in "$@"; do grep -qF -- "$n" err.txt || okk=0; done
  [ ! -e "o_$name" ] || okk=0
  if [ $okk = 1 ]; then ok "$name refused: $(cut -c1-220 err.txt)"; else bad "$name (rc=$rc): $(cat err.txt)"; fi
}

echo "== checkpoint / restart / fluid guard tests"
mk walls.cfg noslip
mk periodic.cfg none
"$PELOID" run walls.cfg --out a 2> /dev/null && [ -f a/checkpoint.h5 ] && ok "walls scene runs" || bad "walls scene"
"$PELOID" run periodic.cfg --out p 2> /dev/null && ok "periodic scene runs" || bad "periodic scene"

# corrupt SRC DST PYTHON: copy and edit with h5py; fix(ds) recomputes the checksum
corrupt() {
  cp "$1" "$2"
  $PY - "$2" "$3" <<'PYEOF'
import sys, h5py, numpy as np
def fnv(b):
    h = 0xcbf29ce484222325
    for x in b:
        h = ((h ^ x) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h
def fix(ds):
    v = fnv(ds[()].tobytes())
    ds.attrs.modify("fnv1a64", np.array([v - (1 << 64) if v >= (1 << 63) else v], dtype="<i8"))
f = h5py.File(sys.argv[1], "a")
exec(sys.argv[2])
f.close()
PYEOF
}

corrupt a/checkpoint.h5 nan.h5 'd = f["fluid/x"]; a = d[()]; a[7] = np.nan; d[...] = a; fix(d)'
CMD=("$PELOID" run walls.cfg --restart nan.h5); refused nan_x "fluid/x[7]" "outside the box"
corrupt a/checkpoint.h5 nanv.h5 'd = f["fluid/vx"]; a = d[()]; a[3] = np.nan; d[...] = a; fix(d)'
CMD=("$PELOID" run walls.cfg --restart nanv.h5); refused nan_vx "fluid/vx[3]" "not finite"
# the top exponent bit of the first x < 2: x becomes ~1e308
corrupt a/checkpoint.h5 flip.h5 'd = f["fluid/x"]; a = d[()]; i = int(np.argmax(a < 2)); b = a.view(np.uint64); b[i] ^= np.uint64(1 << 62); d[...] = a; fix(d)'
CMD=("$PELOID" run walls.cfg --restart flip.h5); refused flipped_exponent_bit "fluid/x[" "e+30" "outside the box"
corrupt a/checkpoint.h5 big.h5 'd = f["fluid/x"]; a = d[()]; a[0] = 1e300; d[...] = a; fix(d)'
CMD=("$PELOID" run walls.cfg --restart big.h5); refused x_1e300 "fluid/x[0] = 1.0000000000000001e+300" "outside the box"
corrupt a/checkpoint.h5 neg.h5 'd = f["fluid/z"]; a = d[()]; a[0] = -1e9; d[...] = a; fix(d)'
CMD=("$PELOID" run walls.cfg --restart neg.h5); refused z_minus_1e9 "fluid/z[0] = -1000000000" "outside the box"
corrupt a/checkpoint.h5 fast.h5 'd = f["fluid/vy"]; a = d[()]; a[2] = 1e6; d[...] = a; fix(d)'
CMD=("$PELOID" run walls.cfg --restart fast.h5); refused v_1e6 "fluid particle 2 has speed" "bound"
corrupt a/checkpoint.h5 step7.h5 'm = f.attrs["peloid_checkpoint"]; m[0] = -7; f.attrs.modify("peloid_checkpoint", m)'
CMD=("$PELOID" run walls.cfg --restart step7.h5); refused step_minus_7 "step -7" "allowed >= 0"
corrupt a/checkpoint.h5 stepbig.h5 'm = f.attrs["peloid_checkpoint"]; m[0] = (1 << 63) - 3; f.attrs.modify("peloid_checkpoint", m)'
CMD=("$PELOID" run walls.cfg --restart stepbig.h5); refused step_2e63 "9223372036854775805" "largest step"
corrupt a/checkpoint.h5 sum.h5 'd = f["fluid/vz"]; a = d[()]; a[1] += 1e-9; d[...] = a'
CMD=("$PELOID" run walls.cfg --restart sum.h5); refused wrong_checksum "/fluid/vz fails its checksum"
corrupt a/checkpoint.h5 sumw.h5 'd = f["wall_impulse"]; a = d[()]; a[0] = 1.5; d[...] = a'
CMD=("$PELOID" run walls.cfg --restart sumw.h5); refused wrong_checksum_wall_impulse "/wall_impulse fails its checksum"
corrupt a/checkpoint.h5 ver.h5 'f.attrs.modify("format_version", np.array([99], dtype="<i8"))'
CMD=("$PELOID" run walls.cfg --restart ver.h5); refused unknown_version "format version 99" "reads version 2"
corrupt a/checkpoint.h5 nover.h5 'del f.attrs["format_version"]'
CMD=("$PELOID" run walls.cfg --restart nover.h5); refused format_1 "format version 1"
corrupt a/checkpoint.h5 keys.h5 'f.attrs.modify("scene_keys", f.attrs["scene_keys"].replace(b"srd.dt = 0.5", b"srd.dt = 0.6"))'
CMD=("$PELOID" run walls.cfg --restart keys.h5); refused fingerprint_mismatch "do not match scene_fingerprint"

# colloids: a position outside the box, an image counter beyond 2^30, an MD
# step counter that the run would overflow
printf 'seed = 2;\nsteps = 5;\nbox: { cells = [8, 8, 8]; };\nfluid: { density = 0.0; };\ncolloids: { count = 8; radius = 1.0; pairs = ""; };\n' > col.cfg
"$PELOID" run col.cfg --out c 2> /dev/null && ok "colloid scene runs" || bad "colloid scene"
corrupt c/checkpoint.h5 cx.h5 'd = f["colloids/y"]; a = d[()]; a[3] = 1e300; d[...] = a; fix(d)'
CMD=("$PELOID" run col.cfg --restart cx.h5); refused colloid_outside "colloids/y[3] = 1.0000000000000001e+300 is outside the box"
corrupt c/checkpoint.h5 ci.h5 'd = f["colloids/iz"]; a = d[()]; a[5] = 2**31 - 5; d[...] = a; fix(d)'
CMD=("$PELOID" run col.cfg --restart ci.h5); refused colloid_image "colloids/iz[5] = 2147483643"
corrupt c/checkpoint.h5 cm.h5 'd = f["colloids/md_step"]; a = d[()]; a[0] = (1 << 62) - 3; d[...] = a; fix(d)'
CMD=("$PELOID" run col.cfg --restart cm.h5); refused colloid_md_step "colloid MD step 4611686018427387901" "largest step"

# restart into a changed physics key
mk dt.cfg noslip 's/dt = 0.5/dt = 10.0/'
CMD=("$PELOID" run dt.cfg --restart a/checkpoint.h5); refused changed_srd_dt "srd.dt 0.5 -> 10" "--restart-changed"
mk temp.cfg noslip 's/temperature = 1.0; body/temperature = 2.0; body/'
CMD=("$PELOID" run temp.cfg --restart a/checkpoint.h5); refused changed_fluid_temperature "fluid.temperature 1 -> 2"
mk rule.cfg noslip 's/random_axis/hecht_axes/'
CMD=("$PELOID" run rule.cfg --restart a/checkpoint.h5); refused changed_srd_rule 'srd.rule "random_axis" -> "hecht_axes"'
mk force.cfg noslip 's/body_force = \[0.0, 0.0, 0.0\]/body_force = [0.001, 0.0, 0.0]/'
CMD=("$PELOID" run force.cfg --restart a/checkpoint.h5); refused changed_body_force "fluid.body_force [0, 0, 0] -> [0.001, 0, 0]"
mk thermo.cfg noslip 's/"heyes"/"rescale"/'
CMD=("$PELOID" run thermo.cfg --restart a/checkpoint.h5); refused changed_thermostat 'thermostat.type "heyes" -> "rescale"'
CMD=("$PELOID" run periodic.cfg --restart a/checkpoint.h5); refused walls_into_periodic 'box.walls_z "noslip" -> "none"'
CMD=("$PELOID" run dt.cfg --restart a/checkpoint.h5 --restart-changed srd.dtx); refused restart_changed_unknown_key "'srd.dtx' is not a scene key"
CMD=("$PELOID" run dt.cfg --restart-changed srd.dt); refused restart_changed_without_restart "needs --restart"
"$PELOID" run dt.cfg --restart a/checkpoint.h5 --restart-changed srd.dt --steps 5 --out o_dt 2> err.txt
[ $? -eq 0 ] && [ -f o_dt/checkpoint.h5 ] && ok "--restart-changed srd.dt accepted" || bad "--restart-changed srd.dt: $(cat err.txt)"
"$PELOID" run thermo.cfg --restart a/checkpoint.h5 --restart-changed thermostat.type,srd.alpha --steps 5 --out o_th 2> err.txt
[ $? -eq 0 ] && ok "--restart-changed with two keys accepted" || bad "--restart-changed two keys: $(cat err.txt)"
mk notphys.cfg noslip 's/steps = 20/steps = 7/; s/thermo_interval = 5/thermo_interval = 3/; s/"base"/"other"/'
"$PELOID" run notphys.cfg --restart a/checkpoint.h5 --out o_np 2> err.txt
[ $? -eq 0 ] && ok "non-physics keys (name, steps, output) may change on restart" || bad "non-physics change: $(cat err.txt)"

# fluid guard: exit 3, one line naming step, particle, bound and parameter;
# thermo.tsv holds finite numbers only
guard() { # guard NAME CFG NEEDLE...
  local name=$1 cfg=$2; shift 2
  "$PELOID" run "$cfg" --out "g_$name" 2> err.txt; local rc=$?
  local okk=1
  [ $rc -eq 3 ] || okk=0
  [ "$(grep -c 'peloid: error' err.txt)" -eq 1 ] || okk=0
  for n in "$@"; do grep -qF -- "$n" err.txt || okk=0; done
  grep -qiE '(^|\s)-?(nan|inf)' "g_$name/thermo.tsv" 2>/dev/null && okk=0
  if [ $okk = 1 ]; then ok "guard $name: $(grep 'peloid: error' err.txt | cut -c1-240)"; else bad "guard $name (rc=$rc): $(cat err.txt)"; fi
}
mk wall1000.cfg noslip 's/box: {/box: { wall_velocity_top = [1000.0, 0.0, 0.0];/' 's/steps = 20/steps = 200/' 's/thermo_interval = 5/thermo_interval = 1/' 's/"heyes"/"none"/'
guard wall_speed_1000 wall1000.cfg "guard fluid_speed: step" "fluid particle" "bound" "box.wall_velocity_"
mk wall1000t.cfg noslip 's/box: {/box: { wall_velocity_top = [1000.0, 0.0, 0.0];/' 's/steps = 20/steps = 200/' 's/thermo_interval = 5/thermo_interval = 1/'
guard wall_speed_1000_thermostat wall1000t.cfg "guard fluid_temperature: step 1:" "bound [0.1, 10]"
mk absurd_dt.cfg none 's/dt = 0.5/dt = 100.0/' 's/body_force = \[0.0, 0.0, 0.0\]/body_force = [0.5, 0.0, 0.0]/' 's/thermo_interval = 5/thermo_interval = 1/'
guard absurd_dt absurd_dt.cfg "guard fluid_speed: step 1:" "lower srd.dt"
mk hot.cfg noslip 's/box: {/box: { wall_velocity_top = [40.0, 0.0, 0.0]; wall_velocity_bottom = [-40.0, 0.0, 0.0];/' 's/type = "heyes"; temperature = 1.0;/type = "heyes"; temperature = 1.0; heyes_epsilon = 0.001; interval = 1000;/' 's/steps = 20/steps = 400/'
guard temperature_runaway hot.cfg "guard fluid_temperature: step" "bound [0.1, 10]" "thermostat"

echo "restart_guard.sh: $pass passed, $fail failed"
[ $fail -eq 0 ]
