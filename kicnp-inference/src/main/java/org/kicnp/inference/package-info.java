/**
 * The inference engine: forward chaining over behavior frames (a TREAT-style match network with hash-indexed
 * alpha memories fed by knowledge base events), an agenda with a stated conflict-resolution order, truth
 * maintenance, explanations, backward chaining, and the coordination of the actions that firings issue.
 * The semantics are written down in {@code docs/inference.md}.
 */
package org.kicnp.inference;
