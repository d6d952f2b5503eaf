/**
 * The JavaScript runtime of K-ICNP: GraalJS behind a narrow interface. Slots of a frame hold JavaScript for
 * procedural demons ({@code onInstantiate}, {@code onNeeded}, ...) and {@code js:} conditions; the inference
 * engine compiles them once with {@link org.kicnp.script.ScriptRuntime#compile} and runs them with
 * {@link org.kicnp.script.ScriptRuntime#run} or {@link org.kicnp.script.ScriptRuntime#test}.
 *
 * <p>Every script runs in a sandbox (no files, processes, threads, environment, native code, other languages,
 * and no Java except explicitly exported members and allow-listed classes), under a statement limit and a
 * wall-clock limit. All contexts share one polyglot engine so parsed code is cached; a context is used by one
 * thread at a time. {@link org.kicnp.script.Proxies} and {@link org.kicnp.script.ScriptValues} build the
 * globals a script sees and turn its results back into plain Java.
 */
package org.kicnp.script;
