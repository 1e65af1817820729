// Lesson 9 — the technique mutation of multiplexed MLT: a neighbouring technique of the same path
// length, with both transition probabilities. Interface: lessons/09-metropolis/mmlt.h. Equation
// numbers refer to lessons/09-metropolis/README.md.
#include "09-metropolis/mmlt.h"
#include "todo.h"

namespace ps {

Proposal mutateTechnique(int s, int k, float u) {
    //! TODO(09) Eq. 9.13: the neighbours of s within 0 .. k are s - 1 and s + 1; from an end
    //!          (s = 0 or s = k) the only one, else s - 1 if u < 1/2, s + 1 otherwise. Return
    //!          Proposal{s', T(s -> s'), T(s' -> s)} with T(a -> b) = 1 / (number of neighbours of a).
    //!          Pitfall: next to an end the two are not equal (1/2 one way, 1 the other): a chain
    //!          that takes them as equal visits the end techniques (s = 0: the camera path hits the
    //!          light; s = k: light tracing) too rarely.
    //! STUB (void)k; (void)u;
    //! STUB return PS_TODO("lesson 09: mutateTechnique", (Proposal{double(s), 1.0, 1.0}));
    //! BEGIN
    const auto neighbours = [k](int a) { return (a > 0 ? 1 : 0) + (a < k ? 1 : 0); };
    const int to = s == 0 ? 1 : s == k ? k - 1 : u < 0.5f ? s - 1 : s + 1;
    return Proposal{double(to), 1.0 / neighbours(s), 1.0 / neighbours(to)};
    //! END
}

}  // namespace ps
