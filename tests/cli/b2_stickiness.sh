#!/usr/bin/env bash
# tools/b2_stickiness.py (issue 39, validation/REPORT.md "Verdicts (issue 39)"): its self-test against
# analytic cases (a few seconds, no peloid run):
#  - B2* of a square well (depth e, range lambda) = 1 - (lambda^3 - 1)(e^e - 1) to 1e-8, by the
#    integrator the DLVO uses, at three (e, lambda);
#  - Baxter's narrow-well limit tau = 1 / (12 (lambda - 1)(e^e - 1)) within 1 %;
#  - Chiew-Glandt tau_p(0.14) = 0.1231;
#  - Hecht Eqs. 1-2 with the study scene's constants: barrier 9.994 kT and secondary minimum -2.935 kT at
#    1.4e8 /m, 20 mV, as `peloid params studies/hecht_fig9_base.cfg` prints them (within 0.01 / 0.002 kT):
#    shown to fail with eps_r = 81 (barrier 11.86 kT).
# The argument (the peloid binary, as for every suite of make check) is not used.
set -u
cd "$(dirname "$0")/../.."
if /usr/bin/python3 tools/b2_stickiness.py --selftest > /tmp/b2_stickiness.$$ 2>&1; then
  echo "  ok   tools/b2_stickiness.py --selftest"
  rm -f /tmp/b2_stickiness.$$
else
  cat /tmp/b2_stickiness.$$; rm -f /tmp/b2_stickiness.$$
  echo "  FAIL tools/b2_stickiness.py --selftest"; exit 1
fi
