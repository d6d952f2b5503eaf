/**
 * The running platform in one process: the durable knowledge store, the inference engine on its own thread, the
 * network gateway and the knowledge editor, wired together ({@link org.kicnp.cli.platform.Platform}), with an event
 * log of everything that happens ({@link org.kicnp.cli.platform.EventLog}). The CLI verbs {@code serve},
 * {@code replay} and {@code demo} start it.
 */
package org.kicnp.cli.platform;
