//! Pixel samplers: the interface a renderer drives (in progress).
