/**
 * Benchmarks behind {@code ./kicnp bench}: K-ICNP's components measured side by side with established peers, which
 * live here only and never in the platform at run time.
 */
package org.kicnp.bench;
