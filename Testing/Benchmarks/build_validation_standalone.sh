#!/usr/bin/env bash
# Usage: build_validation_standalone.sh <tree> <out>  (JOBS compile jobs at once, default nproc;
# EIGEN_INCLUDE: the directory holding Eigen/, default /usr/include/eigen3).
# Builds the SPH validation program of a tree (argument: its root) into $2 with the product's
# per-file flags (Release -O3, OpenMP; delta-SPH's files without errno and trapping; the
# neighbour search without contraction).
set -euo pipefail
root=$1; out=$2; mkdir -p "$out/obj"
inc="-I$root/Filters/Common/Core -I$root/Filters/SPH/Core -I$root/Testing/SPH/Validation -isystem ${EIGEN_INCLUDE:-/usr/include/eigen3}"
objs=()
for f in $root/Filters/Common/Core/*.cxx $root/Filters/SPH/Core/*.cxx $root/Testing/SPH/Validation/*.cxx $root/Testing/Benchmarks/SPHValidation.cxx; do
  extra=""
  case $(basename $f) in
    DeltaSPH*.cxx) extra="-fno-math-errno -fno-trapping-math";;
    CandidateHits.cxx) extra="-ffp-contract=off";;
  esac
  o="$out/obj/$(echo $f | md5sum | cut -c1-8)_$(basename $f).o"
  objs+=("$o")
  (g++ -std=c++17 -O3 -DNDEBUG -fopenmp $extra $inc -c "$f" -o "$o") &
  while [ "$(jobs -r | wc -l)" -ge "${JOBS:-$(nproc)}" ]; do sleep 0.2; done
done
wait
g++ -fopenmp "${objs[@]}" -o "$out/ParaFluidSPHValidation"
