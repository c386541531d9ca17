#!/usr/bin/env bash
# The distributed SPH run's tests and strong-scaling benchmark on the 16-core GPU machine (no
# ParaView there): a core-only build (build-dev/) with GoogleTest and Eigen from .deps (see
# gpu-tests.sh), the DistributedSimulation tests, then ParaFluidDistributedBenchmark at 200k and
# 1.6M particles on 1-16 processes; the figures also go to $OUT when it is set.
set -euo pipefail
OUT="${OUT:-/tmp}"
root=$PWD; build=$root/build-dev
cmake -S .deps/googletest -B $build/gt -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=$build/gti >/dev/null
cmake --build $build/gt --parallel 16 --target install >/dev/null
cmake -S . -B $build -DCMAKE_BUILD_TYPE=Release -DPARAFLUID_CORE_ONLY=ON -DPARAFLUID_BUILD_BENCHMARKS=OFF -DPARAFLUID_CUDA=OFF -DCMAKE_PREFIX_PATH="$build/gti;$root/.deps/eigen" >/dev/null
cmake --build $build --parallel 16 --target ParaFluidSPHCoreTests ParaFluidDistributedBenchmark 2>&1 | tail -2
t=$(find $build -name ParaFluidSPHCoreTests -type f | head -1); b=$(find $build -name ParaFluidDistributedBenchmark -type f | head -1)
lscpu | grep -E "Model name|^CPU\(s\)|Thread" | tee $OUT/cpu.txt
OMP_WAIT_POLICY=PASSIVE $t --gtest_filter='Distributed*' 2>&1 | tail -3 | tee $OUT/tests.txt
OMP_NUM_THREADS=1 $b 200000 30 16 1 | tee $OUT/bench200k.txt
OMP_NUM_THREADS=1 $b 1600000 10 16 1 | tee $OUT/bench1600k.txt
