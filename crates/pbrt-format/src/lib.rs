//! Parser for the pbrt-v4 scene-file format, with file:line:column errors. (in progress)
