// The standard figures of a run folder, as SvgFigure values (run_writer writes them). Each copes
// with partial results: a failed run gives the same figures with what it has ("no data" at worst).
#pragma once

#include <vector>

#include "output/fld.h"
#include "output/svg_plot.h"
#include "run/run_result.h"
#include "scene/scene.h"

namespace vs {

// Punch force [kN] vs punch travel [mm].
SvgFigure load_travel_figure(const Scene& scene, const RunResult& result);

// Thickness strain vs initial radius, one line per profile travel.
SvgFigure thickness_strain_figure(const Scene& scene, const RunResult& result);

// Meridional, circumferential and thickness strain vs initial radius at the final state.
SvgFigure strains_figure(const Scene& scene, const RunResult& result);

// Deformed meridians (z vs r, equal aspect), one per profile travel.
SvgFigure deformed_stages_figure(const Scene& scene, const RunResult& result);

// Forming limit diagram: final major vs minor strain of every element, the strain paths, and the
// forming-limit curve with the curve lowered by its safety margin (dashed) when there is one.
SvgFigure fld_figure(const Scene& scene, const RunResult& result,
                     const std::vector<StrainPath>& paths, const FormingLimitCurve& flc = {});

}  // namespace vs
