// Lesson 9 — the bootstrap of PSSMLT: b and where the chains start. Interface:
// lessons/09-metropolis/pssmlt.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/pssmlt.h"
#include "todo.h"

namespace ps {

Bootstrap bootstrapChains(const std::vector<float>& I, int chains, Rng& rng) {
    //! TODO(09) b and the chains' stratified starts of Eq. 9.10, as bootstrapChains in pssmlt.h states them (one number
    //!          per chain, in chain order). Pitfall: a point past the CDF's end by rounding starts at the last seed
    //!          with I > 0.
    //! STUB (void)I; (void)chains; (void)rng;
    //! STUB return PS_TODO("lesson 09: bootstrapChains", Bootstrap{});
    //! BEGIN
    Bootstrap out;
    std::vector<double> cdf(I.size());
    double sum = 0.0;
    size_t last = 0;
    for (size_t i = 0; i < I.size(); ++i) {
        sum += double(I[i]);
        cdf[i] = sum;
        if (I[i] > 0.0f) last = i;
    }
    if (!(sum > 0.0)) return out;
    out.b = sum / double(I.size());
    for (int c = 0; c < chains; ++c) {
        const double target = (c + double(rng.uniform())) / chains * sum;
        const size_t i = size_t(std::upper_bound(cdf.begin(), cdf.end(), target) - cdf.begin());
        out.starts.push_back(uint32_t(std::min(i, last)));
    }
    return out;
    //! END
}

}  // namespace ps
