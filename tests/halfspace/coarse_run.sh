#!/usr/bin/env bash
# Runs a comparison case on 1.32 mm cells (four times the paper's) with four
# times the paper's step into ./h1.32 (the case file is ./case.prm), for the
# coarse comparison tests compare_coulomb_01 and compare_exponential_01.
# Arguments: the wheelrail executable, the case file.
set -euo pipefail
exe=$1 base=$2
rm -rf h1.32
cat > case.prm <<PRM
include $base
subsection Problem
  set Output directory = h1.32
end
subsection Geometry
  subsection Mesh
    set Minimum cell size = 0.00132
  end
end
subsection Time integration
  set Time step = 1.04e-7
end
PRM
"$exe" case.prm > wheelrail.log
