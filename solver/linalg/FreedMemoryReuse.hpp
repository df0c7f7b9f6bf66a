#pragma once
/// \file FreedMemoryReuse.hpp
/// Large blocks freed by one factorisation kept for the next instead of handed back to the
/// system. glibc's malloc maps every block above 32 MB afresh and unmaps it when freed (a
/// thread's own arena, every block above 64 MB), so each LU factorisation — UMFPACK frees and
/// reallocates its numeric factor, hundreds of megabytes — paid the first touch of every page
/// again: on a 13,500-element tunnel with ψ = 0 the page faults and the zeroing of fresh pages
/// were half the time of its factorisations (docs/benchmarks.md, "Freed memory kept for the
/// next factorisation").

namespace mcdda {

/// Sets the process's malloc parameters (once; glibc only): no block from mmap, no trimming of
/// the heap's free top below 2 GB, one arena for all threads (the desktop program solves in a
/// thread of its own). Programs call it first thing, before they start threads; a SymmetricSystem
/// calls it too, for programs that use the library without it.
void reuse_freed_memory();

/// While one is alive, freed memory stays in the heap; the last one to go returns it to the
/// system, so a program that ran a model does not keep its peak.
class FreedMemoryReuse {
public:
    FreedMemoryReuse();
    ~FreedMemoryReuse();
    FreedMemoryReuse(const FreedMemoryReuse&) = delete;
    FreedMemoryReuse& operator=(const FreedMemoryReuse&) = delete;
};

}  // namespace mcdda
