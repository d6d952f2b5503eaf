/**
 * The browser knowledge-base editor (the paper's figures 3 and 4): a Jetty 12 server with a JSON API over the
 * {@link org.kicnp.core.KnowledgeBase}, a WebSocket that pushes knowledge changes live, and one static page that
 * shows the IS-A hierarchy as clickable buttons and a slot editing table per frame, and, when connected to a live
 * platform through the {@link org.kicnp.editor.PlatformPorts} ({@link org.kicnp.editor.WorldView},
 * {@link org.kicnp.editor.ChatPort}, {@link org.kicnp.editor.TeleOperation}), a World panel: the room drawn live, a
 * chat with the robots and tele-operation. Start it with
 * {@link org.kicnp.editor.EditorServer#start}.
 */
package org.kicnp.editor;
