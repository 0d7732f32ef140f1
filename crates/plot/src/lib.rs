//! Small plotting helpers writing PNG and SVG (in progress).
