/**
 * The benchmarks behind {@code ./kicnp bench}: K-ICNP's components measured on generated data, side by side with
 * established peers where there are some. Each prints a readable table followed by one JSON line, so that people
 * and scripts read the same run. The peers live here only and never in the platform at run time.
 */
package org.kicnp.bench;
