#!/usr/bin/env bash
# Snakemake --cluster-status for SLURM: prints running, success or failed for one job id
# (sbatch --parsable prints "id" or "id;cluster"). Asks scontrol (works without accounting while
# the controller keeps finished jobs, MinJobAge), then sacct.
id=${1%%;*}
state=$(scontrol show job -o "$id" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2)
if [ -z "$state" ]; then
  state=$(sacct -n -X -P -j "$id" -o State 2>/dev/null | head -n1 | cut -d' ' -f1)
fi
case $state in
  COMPLETED) echo success ;;
  PENDING|RUNNING|CONFIGURING|COMPLETING|SUSPENDED|REQUEUED|RESIZING|"") echo running ;;
  *) echo failed ;;
esac
