#!/usr/bin/env bash
# The main job on a fresh machine: install, build, run the default case (a dam break,
# about a minute on two cores) and print its surge front. Output goes to runs/quickstart/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
bash tools/build.sh
./build/cpp_driver/sphjet run cases/quickstart/dambreak.toml --out runs/quickstart --force
./build/cpp_driver/sphjet analyse runs/quickstart --front --csv runs/quickstart/front.csv
echo "ParaView: open runs/quickstart/sphjet.xmf; legacy PART files, DT and front.csv are beside it."
