// The build the apps come from (--version, summary.json "version" and "commit"): the generated header
// changes with the commit, and only this file is compiled again.
#include "polymech_version.hpp"

namespace polymech::apps {
const char* version() { return POLYMECH_VERSION; }
const char* commit() { return POLYMECH_GIT_COMMIT; }
}  // namespace polymech::apps
