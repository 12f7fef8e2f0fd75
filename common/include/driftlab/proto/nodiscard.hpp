// DRIFTLAB_NODISCARD: C++14 has no [[nodiscard]], so fallible functions carry GCC's warn_unused_result instead.
#pragma once

#if defined(__GNUC__)
#define DRIFTLAB_NODISCARD __attribute__((warn_unused_result))
#else
#define DRIFTLAB_NODISCARD
#endif
