// `vshell fit-hardening CSV --law swift|voce|hollomon|all [-o DIR] [--elastic-modulus-MPa E]
// [--max-strain X] [--allow-past-maximum]`: fits hardening laws to a measured tensile curve
// (inverse/tensile_fit.h) and writes fit.json, fit_<law>.csv and fit.svg. Input errors print one
// line "error: ..." and exit with code 2.
#pragma once

namespace CLI {
class App;
}

namespace vs {

void add_fit_hardening_command(CLI::App& app);

}  // namespace vs
