/**
 * The value codec: wire format version 1 for values, as specified in {@code docs/protocol.md}.
 *
 * <p>{@link dev.trade.internal.codec.Codec} encodes and decodes values, and copies them for
 * strict-mode local calls. {@link dev.trade.internal.codec.ByteSink} and
 * {@link dev.trade.internal.codec.ByteSource} are the buffers that frames share with it.
 * {@link dev.trade.internal.codec.AllowList} and {@link dev.trade.internal.codec.Limits} bound
 * what decoding may load and allocate. {@link dev.trade.internal.codec.InfoBinding} connects the
 * codec to the container's service infos. The package is internal: the module does not export it.
 */
package dev.trade.internal.codec;
