//! Point-set quality metrics: star discrepancy (exact and bounds), L2-type discrepancies, minimum distance, spectra. (in progress)
