# Shared helpers of the benchmark scripts (sourced, not run).
# med: median, min and max of the numbers on stdin, one per line.
med() { sort -g | awk '{a[NR]=$1} END{m=(NR%2)?a[(NR+1)/2]:(a[NR/2]+a[NR/2+1])/2; printf "%.4g %.4g %.4g\n", m, a[1], a[NR]}'; }
# MPIRUN: the peers' MPI launch, one rank per core.
MPIRUN="mpirun --allow-run-as-root --oversubscribe --bind-to core"
# lammps_version: "LAMMPS <date>" of the installed lmp.
lammps_version() { lmp -h | grep -m1 'Parallel Simulator' | sed 's/.*Simulator - /LAMMPS /'; }
