; listing: fatmap2 sec. 15 8:15 tiled loop
; source: Byggmastar, fatmap2.txt (1997), sec. 15, 8:15 bit tiled (8x8 tiles) inner loop
; cpu: pentium
; published: 6 cycles per pixel
; pixels: 1
; branch: none
; note: 32-bit flat; loop-closing branch is the final jnz (taken, predicted) on the flags of inc ecx (the instructions after it leave flags alone); ECX runs from -width up to 0; tildudx and tildvdx are memory operands; worked out on paper by the author, no pairing/cache effects counted beyond his
;
; u and v are kept with their bits spread so that u+v, shifted right 16,
; is the byte offset inside a 256x256 texture stored as 8x8 tiles; the gap
; bits in the steps are ones so carries ripple across them, and the AND
; masks clear them again. EBP holds u+v from the previous pass, ESI the
; texture base, EDI one before the end of the span.

bits 32

tildudx equ 0x1000                      ; dword: tiled u step
tildvdx equ 0x1004                      ; dword: tiled v step

inner:
        add     eax,[tildudx]           ; u += step
        add     ebx,[tildvdx]           ; v += step
        shr     ebp,16                  ; texel offset from previous u+v
        and     eax,11111000000001110111111111111111b   ; clear u gap bits
        and     ebx,00000111111110000111111111111111b   ; clear v gap bits
        inc     ecx
        mov     dl,[esi+ebp]            ; fetch texel
        lea     ebp,[eax+ebx]           ; u+v for the next pass
        mov     [edi+ecx],dl            ; store pixel
        jnz     inner
