#pragma once
// An allocator whose memory starts zeroed without being touched: calloc hands large blocks out as
// fresh pages the kernel maps on first write, and value-initialisation writes nothing. A vector
// of N doubles then costs resident memory only where something other than +0 is written (a
// ZCORN store that will be refused, or one full of zero depths, stays small).
#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>

namespace cutaway::grid {

template <class T>
struct ZeroedAllocator {
    using value_type = T;
    ZeroedAllocator() = default;
    template <class U>
    explicit ZeroedAllocator(const ZeroedAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        void* memory = std::calloc(n, sizeof(T));
        if (memory == nullptr) throw std::bad_alloc();
        return static_cast<T*>(memory);
    }
    void deallocate(T* memory, std::size_t) noexcept { std::free(memory); }

    /// Value-initialisation: the memory is already zero (T must be zero when all its bytes are).
    template <class U>
    void construct(U*) noexcept {}
    template <class U, class... Args>
    void construct(U* place, Args&&... args) {
        ::new (static_cast<void*>(place)) U(std::forward<Args>(args)...);
    }

    template <class U>
    bool operator==(const ZeroedAllocator<U>&) const noexcept { return true; }
};

}  // namespace cutaway::grid
