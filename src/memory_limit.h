// How much memory one process may take, and capping a loader process to it.
#pragma once

#include <string>

namespace pd {

/// The memory this process may use in all, in MB: the machine's physical
/// memory, or the cgroup's limit (a container's `memory.max`) when lower.
/// 0 when neither can be read.
double available_memory_mb();

/// Share of available_memory_mb() each of `processes` loader processes may
/// allocate: half of it split evenly, so the loaders together can never push
/// the machine into swap or its OOM killer, whatever files they read. 0 when
/// the available memory is unknown.
double memory_share_mb(double available_mb, int processes);

/// The default of --memory: what the stages that hold part surfaces keep for
/// reuse (batch/refine.cpp), in MB: an eighth of the available memory, at
/// least 256 MB and at most 1024 (1024 when the available memory is unknown).
double memory_budget_mb(double available_mb);

/// A --memory value in MB: a number of MB, or one with a unit K, M, G or T
/// (powers of 1024; "512M", "1.5G"). Throws std::invalid_argument naming the
/// value when it is none of these or not positive.
double parse_memory_mb(const std::string& text);

/// Caps this process's address space at what it maps now plus `mb` MB
/// (RLIMIT_AS), so a reader that allocates without end gets std::bad_alloc
/// (or dies) instead of the machine's memory. Returns false, changing
/// nothing, when `mb` <= 0, when the limit cannot be set, or in an
/// AddressSanitizer build (its shadow memory is terabytes of address space).
bool cap_address_space_growth(double mb);

/// Whether cap_address_space_growth can work in this build (not under ASan).
bool can_cap_address_space();

}  // namespace pd
