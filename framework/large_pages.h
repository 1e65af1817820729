// An allocator for the large arrays that every ray reads (the BVH's wide nodes, the scene's
// triangles in leaf order): an array of 2 MB or more starts on a 2 MB boundary and, on Linux,
// the kernel is asked (madvise) to back it with 2 MB pages where it can. A ray that walks a
// tree of several MB touches a new 4 KB page at nearly every node, and a page the processor's
// TLB does not hold costs a page-table walk; 2 MB pages make the nodes of a whole mesh fit in a
// few dozen TLB entries (bench/README.md: shadow rays on the motorbike ~15 % faster). Smaller
// arrays, and every other system, get plain cache-line-aligned memory. The kernel may refuse
// (transparent huge pages off): the array then lives on 4 KB pages, which is only slower.
#pragma once
#include <cstddef>
#include <new>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace ps {

template <class T>
struct LargePageAllocator {
    using value_type = T;
    static constexpr size_t kLargePage = size_t(2) << 20;

    LargePageAllocator() = default;
    template <class U>
    LargePageAllocator(const LargePageAllocator<U>&) {}

    static size_t alignment(size_t bytes) {
        return bytes >= kLargePage ? kLargePage : (alignof(T) > 64 ? alignof(T) : 64);
    }
    T* allocate(size_t n) {
        const size_t bytes = n * sizeof(T), align = alignment(bytes);
        // Whole 2 MB pages: the last one is not shared with anything else.
        const size_t size = (bytes + align - 1) / align * align;
        void* p = ::operator new(size, std::align_val_t(align));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        if (align == kLargePage) madvise(p, size, MADV_HUGEPAGE);  // a hint: its failure is harmless
#endif
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t n) { ::operator delete(p, std::align_val_t(alignment(n * sizeof(T)))); }

    template <class U>
    bool operator==(const LargePageAllocator<U>&) const {
        return true;
    }
    template <class U>
    bool operator!=(const LargePageAllocator<U>&) const {
        return false;
    }
};

}  // namespace ps
