/**
 * Authentication primitives shared by discovery and links: {@link
 * dev.trade.internal.crypto.HmacSha256}, the HMAC that signs announcements, proves credentials in
 * the link handshake and derives the keys of encrypted links. The package is internal: the module
 * does not export it.
 */
package dev.trade.internal.crypto;
