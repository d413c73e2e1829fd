//! Accuracy and speed, measured: work-precision rows and the numerical stress test.
