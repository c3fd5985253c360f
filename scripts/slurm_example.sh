#!/usr/bin/env bash
# An example Slurm batch script: a magfem study (or sweep, validate, actuator --verify) dealt
# to the processes of a cluster job. Copy it, change the #SBATCH lines and the command for
# your cluster and case, and submit it with `sbatch scripts/slurm_example.sh`.
#
# What scales: the items of a study (designs), a sweep (positions), validate (catalogue
# entries) and actuator --verify (verification solves) are independent, and rank 0 deals them
# one at a time to whichever process asks next, so N processes finish up to N times sooner
# when there are many more items than processes. Each process solves its items on its own
# threads (its share of its node's cores), holding one whole mesh per item at a time: memory
# per node does not fall with N. What does not scale: `magfem optimize` (each step depends on
# the one before: refused under mpirun), and `magfem solve` of one case (distributed, but every
# process meshes the whole case; it lets a linear 3D case use several nodes' memory, it is not
# faster than one process on one node). docs/performance.md has the design and measurements.
#
# Rank 0 alone writes: the outputs (the serial --jobs 1 run's, byte for byte but for times)
# and the checkpoint, so a job that runs out of time can be resubmitted with --resume (with or
# without mpirun). Every process ends with the same exit code (0 ok, 2 bad input, 3 some
# designs or positions failed, 4 validation failures).

#SBATCH --job-name=magfem-study
#SBATCH --nodes=4                 # machines
#SBATCH --ntasks-per-node=1       # one magfem process per machine: it threads over the cores
#SBATCH --cpus-per-task=16        # the cores each process may use
#SBATCH --mem=0                   # all of each node's memory (the memory guard shares it)
#SBATCH --time=04:00:00
#SBATCH --output=magfem-study-%j.log

set -euo pipefail

# The build and the case on a file system every node sees; the output folder too (rank 0
# writes it, and --resume reads the checkpoint there).
MAGFEM=${MAGFEM:-$HOME/magfem/build/magfem}
CASE=${CASE:-$HOME/magfem/examples/3d/compensator_study.yaml}
OUT=${OUT:-$HOME/magfem-runs/compensator_study}

# Each process's threads: its element loops use the cores Slurm gave its task.
export MAGFEM_THREADS=${SLURM_CPUS_PER_TASK:-1}
export OMP_NUM_THREADS=1 # one BLAS thread per solve (magfem sets it for dealt items anyway)

# srun starts one magfem per task; `mpirun -n $SLURM_NTASKS` works as well where the MPI
# library is not built with Slurm's PMI. --resume: a resubmitted job continues where the
# last one stopped (a fresh folder simply starts from the beginning).
srun "$MAGFEM" study "$CASE" \
  --param R_out=40:1:70 --param R_in=25:1:40 \
  --objective peak_torque --rotate outer --axis y --angles 0:10:180 \
  --fe --mesh-scale 2 --resume --out "$OUT"
