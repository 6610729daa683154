// The numbers of `quaternia orbit` and `quaternia cycles` (algebra/constant_text.h): --c and --z0
// read by parseConstant, and formatQuaternion, whose text those options are documented to read
// back. A UserError is a clean rejection; an accepted constant must be finite and survive the trip
// through its printed form to within the 10 digits printed.
#include <algorithm>
#include <cmath>

#include "fuzz/fuzz_check.h"
#include "quaternia/algebra/constant_text.h"
#include "quaternia/util/error.h"

using namespace quaternia;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(fuzzText(data, size));
    Quaternion value;
    try {
        value = parseConstant(text, "--c");
    } catch (const UserError& e) {
        FUZZ_CHECK(e.key() == "--c");
        return 0;
    }
    FUZZ_CHECK(isFinite(value));
    const std::string printed = formatQuaternion(value);
    Quaternion back;
    try {
        back = parseConstant(printed, "--c");
    } catch (const UserError& e) {
        std::fprintf(stderr, "'%s' printed as '%s', which does not read back: %s\n", text.c_str(),
                     printed.c_str(), e.what());
        FUZZ_CHECK(false);
    }
    const double largest =
        std::max({1.0, std::abs(value.w), std::abs(value.x), std::abs(value.y), std::abs(value.z)});
    for (int k = 0; k < 4; ++k)
        FUZZ_CHECK(std::abs(back[k] - value[k]) <= 1e-9 * std::abs(value[k]) + 1e-12 * largest);
    const std::string complex = formatComplex({value.w, value.x});
    FUZZ_CHECK(!complex.empty() && complex.find('j') == std::string::npos);
    return 0;
}
