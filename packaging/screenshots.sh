#!/usr/bin/env bash
# Takes the README/docs screenshots under Xvfb (a real X server at 1920x1080), from a Release build.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/release/app/gui/millexpert
[ -x "$bin" ] || { cmake --preset release -G Ninja && cmake --build --preset release --target millexpert; }
mkdir -p docs/screenshots
shot() { xvfb-run -a -s "-screen 0 1920x1080x24" "$bin" "$@" 2> >(grep -v XDG_RUNTIME_DIR >&2); }
shot projects/rubio2006-tool-selection.mxproj --screenshot docs/screenshots/main-window.png
shot projects/rubio2006-tool-selection.mxproj --point 5100,1.2,0.1 --screenshot docs/screenshots/chatter.png
shot projects/benchmark-insperger-1dof.mxproj --screenshot docs/screenshots/insperger-benchmark.png
shot projects/rubio-pareto-case.mxproj --pareto --docks paretoFrontDock,paretoWeightsDock --screenshot docs/screenshots/pareto-front.png
shot projects/rubio-pareto-case.mxproj --pareto --docks monitoringDock,operatorRulesDock --screenshot docs/screenshots/pareto-monitoring.png
shot projects/rubio2006-adaptive-control.mxproj --docks controlDock --screenshot docs/screenshots/force-control.png
shot projects/rubio-pareto-case.mxproj --docks controlDock --screenshot docs/screenshots/force-control-programme.png
shot projects/cus-zuperl-sdnrp.mxproj --sdnrp --docks surfaceFinishDock --screenshot docs/screenshots/surface-finish.png
shot projects/cus-zuperl-sdnrp.mxproj --program projects/programs/pocket_mm.nc --docks partProgramDock --screenshot docs/screenshots/part-program.png
shot projects/landers-face-milling.mxproj --supervise smc2 --docks supervisorDock --screenshot docs/screenshots/supervisor.png
echo "screenshots written to docs/screenshots/"
shot projects/tap-test-example.mxproj --fit-tap-test x --screenshot docs/screenshots/tap-test.png
shot projects/tap-test-example.mxproj --method sdm --fit-tap-test y --screenshot docs/screenshots/tap-test-lobes-sdm.png
