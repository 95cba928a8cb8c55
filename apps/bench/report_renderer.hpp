// report.html for `navfuse bench`: rendered by apps/bench/report.py (matplotlib, from Debian's
// python3-matplotlib) from the metrics.json and CSVs bench has written into the report folder.
// The script is compiled into the navfuse binary (embed_text.cmake), so an installed navfuse
// needs no source tree; it is run with the interpreter in $NAVFUSE_PYTHON, else Debian's
// /usr/bin/python3 (where python3-matplotlib installs), else python3 on the PATH.
#pragma once

#include <string>

namespace navfuse::apps::bench {

// Runs the report script on `dir`; throws CommandError (naming the interpreter and what to
// install) when Python or matplotlib is missing or the script fails.
void render_report_html(const std::string& dir);

// The script's text (for tests and `--report-script`-style debugging).
const char* report_script();

}  // namespace navfuse::apps::bench
