#pragma once

// A monotonic memory arena on the stack for the working vectors of one cone construction.
// Private to the geometry layer.

#include <cstddef>
#include <new>
#include <vector>

// Private to the geometry layer: hidden from the shared library's interface.
namespace momentlab {
namespace [[gnu::visibility("hidden")]] geometry_detail {

// The working vectors of one angular analysis (items, their ties, groups, the scan's stack) come
// from a buffer on the stack while they fit, so a cone of a few generators makes no allocation
// beyond its own representation; bigger ones spill to the heap. A monotonic arena, written
// here: the WebAssembly build's standard library has no <memory_resource>.
struct Scratch {
    alignas(std::max_align_t) std::byte buffer[6144];
    std::size_t used = 0;

    void* allocate(std::size_t bytes, std::size_t align) {
        const std::size_t start = (used + align - 1) / align * align;
        if (align <= alignof(std::max_align_t) && start + bytes <= sizeof buffer) {
            used = start + bytes;
            return buffer + start;
        }
        return ::operator new(bytes, std::align_val_t(align));
    }
    void deallocate(void* p, std::size_t align) {
        const auto* b = static_cast<const std::byte*>(p);
        if (b >= buffer && b < buffer + sizeof buffer) return;  // freed with the buffer
        ::operator delete(p, std::align_val_t(align));
    }
};

// A standard allocator over a Scratch (implicit from Scratch*, so a vector is made from one).
template <class T>
struct ScratchAllocator {
    using value_type = T;
    Scratch* scratch;
    ScratchAllocator(Scratch* s) : scratch(s) {}  // NOLINT(google-explicit-constructor)
    template <class U>
    ScratchAllocator(const ScratchAllocator<U>& other) : scratch(other.scratch) {}  // NOLINT
    T* allocate(std::size_t n) { return static_cast<T*>(scratch->allocate(n * sizeof(T), alignof(T))); }
    void deallocate(T* p, std::size_t) { scratch->deallocate(p, alignof(T)); }
    template <class U>
    bool operator==(const ScratchAllocator<U>& other) const { return scratch == other.scratch; }
};

template <class T>
using ScratchVector = std::vector<T, ScratchAllocator<T>>;

}  // namespace geometry_detail
}  // namespace momentlab
