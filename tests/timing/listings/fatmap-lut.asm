; listing: fatmap sec. 13 table-lookup loop
; source: Byggmastar, fatmap.txt (1996), sec. 13, one-pixel-per-pass lookup-table inner loop
; cpu: pentium
; published: 4 cycles per pixel
; pixels: 1
; branch: none
; note: 32-bit flat; loop-closing branch is the final jnz (taken, predicted); EBX is loaded from the table one pass ahead of its use as an index; author's figure assumes perfect pairing and no cache misses
;
; The texel offsets for the whole scanline are precomputed once per triangle
; in a dword table (EDX walks it); ESI is the texture pointer (already offset
; by the scanline's starting u,v), EDI the destination, EBP the count.

bits 32

inner:
        mov     al,[esi+ebx]            ; fetch texel
        mov     ebx,[edx]               ; offset of the next texel
        mov     [edi],al                ; store pixel
        add     edx,4
        inc     edi
        dec     ebp
        jnz     inner
