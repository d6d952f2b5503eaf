/**
 * The benchmarks behind {@code ./kicnp bench}: each measures one part of the platform on generated data and
 * prints a readable table followed by one JSON line, so that people and scripts read the same run. This module
 * may carry peer engines (such as Drools) for comparison; nothing at run time depends on it.
 */
package org.kicnp.bench;
