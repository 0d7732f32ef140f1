//! Physically based path tracer driven by lowdisc's pixel samplers. (in progress)
