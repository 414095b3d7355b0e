// `vshell calibrate CONFIG [-o DIR] [--quiet]`: runs a calibration with the real solver and
// writes the report folder. Input errors print one line "error: ..." and exit with code 2.
#pragma once

namespace CLI {
class App;
}

namespace vs {

void add_calibrate_command(CLI::App& app);

}  // namespace vs
