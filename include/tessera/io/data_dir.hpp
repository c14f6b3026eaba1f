#pragma once
// Where the real datasets are (../shared/DESIGN.md "Data"): the one setting TESSERA_DATA_DIR, and
// when it is unset or empty (an empty variable counts as unset) the ../shared/data beside the
// source tree this build was made from. Tests, benchmarks and the CLI all ask here.
#include <filesystem>

namespace tessera {

/// $TESSERA_DATA_DIR if set and not empty, else <source tree>/../shared/data. Does not check that
/// the folder exists (a caller that needs a dataset says which one is missing).
[[nodiscard]] std::filesystem::path data_dir();

}  // namespace tessera
