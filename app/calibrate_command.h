// `vshell calibrate CONFIG [-o DIR] [--quiet]`: runs a calibration with the real solver and
// writes the report folder. Input errors throw InputError (vshell prints one line "error: ..."
// and exits with code 2); a calibration that fails (no usable point) sets `exit_code` to 3 after
// printing the reason as one line on stderr.
#pragma once

namespace CLI {
class App;
}

namespace vs {

void add_calibrate_command(CLI::App& app, int& exit_code);

}  // namespace vs
