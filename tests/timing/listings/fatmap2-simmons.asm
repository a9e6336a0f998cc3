; listing: fatmap2 sec. 13 8:16 loop (Russel Simmons)
; source: Byggmastar, fatmap2.txt (1997), sec. 13, 8:16 bit inner loop by Russel Simmons (left-to-right version)
; cpu: pentium
; published: 4 cycles per pixel
; pixels: 1
; branch: none
; note: 32-bit flat; loop-closing branch is the final jnz (taken, predicted) on the flags of inc ecx; ECX runs from -width up to 0; author's figure assumes perfect pairing and no cache misses
;
; EBX = 64K-aligned 256x256 texture base with v integer in BH and u integer
; in BL. The fractions live in the top 16 bits of EDX (v, step in EBP) and
; EAX (u, step in ESI); the carries feed ADC into BH/BL together with the
; integer steps held in DH (v) and DL (u). EDI points just past the span.

bits 32

inner:
        mov     al,[ebx]                ; fetch texel
        add     edx,ebp                 ; v fraction
        adc     bh,dh                   ; v integer + step + carry
        add     eax,esi                 ; u fraction
        adc     bl,dl                   ; u integer + step + carry
        mov     [edi+ecx],al            ; store pixel
        inc     ecx
        jnz     inner
