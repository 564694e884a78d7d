#!/bin/bash
# trial.sh NAME "icacam deck args" [awk-free sed script file or -] : runs ccx in NAME/, prints time & last .sta line
name=$1; args=$2; edit=$3
mkdir -p $name; cd $name
/work/wt-fe/build/host_tools/icacam fe deck $args > job.inp
if [ -n "$edit" ]; then python3 /work/wt-fe/build/fe-trials/$edit job.inp; fi
start=$(date +%s.%N)
OMP_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 timeout 1800 nice -n 5 ccx -i job > ccx.log 2>&1
end=$(date +%s.%N)
echo "$name wall $(echo "$end - $start" | bc) s; last time: $(tail -1 job.sta)"; grep -m1 -E "ERROR|Job finished" ccx.log
