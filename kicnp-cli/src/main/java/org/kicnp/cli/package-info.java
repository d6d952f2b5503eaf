/** The {@code ./kicnp} command line: one class per verb, wiring the platform's modules together. */
package org.kicnp.cli;
