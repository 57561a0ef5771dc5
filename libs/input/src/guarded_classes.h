// Decoders that stand in for MRPT's where MRPT 2.5.8 crashes on corrupt data
// (doc/robustness.md). Registered under MRPT's own class names, so every
// rawlog object of that class is read through them.
#pragma once

namespace pmap::input {

/// Registers the guarded decoders in MRPT's class registry unless they are
/// there already (MRPT's registerAllClasses_*() puts its own back).
void registerGuardedClasses();

}  // namespace pmap::input
