// The kit's folders as the build configured them. Compiled into one small file (kit_folders.cpp)
// rather than into each file that reads them: a compile command that names no absolute path is
// the same in every copy of the kit, so ccache, where installed, reuses one copy's objects in
// another (the project's own tests build the student release and the Gradescope kit again).
#pragma once

namespace raylab {

// The kit's top folder (scenes/, docs/, assignments/ ...).
const char* kit_source_folder();
// The reference data the grader reads and the regenerate tool writes: autograder/reference.
const char* kit_reference_folder();

}  // namespace raylab
