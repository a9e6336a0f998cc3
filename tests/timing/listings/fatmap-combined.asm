; listing: fatmap sec. 9 loop C (combination)
; source: Byggmastar, fatmap.txt (1996), sec. 9, third inner loop ("combination" of 32-bit u interpolation and byte carry for v)
; cpu: pentium
; published: 5 cycles per pixel
; pixels: 1
; branch: none
; note: 32-bit flat; loop-closing branch is the final jnz (taken, predicted); register-only, no memory variables; author's figure assumes perfect pairing and no cache misses
;
; u is 24.8 in ECX (step in ESI), its integer byte copied to BL; v is kept as
; byte pairs: fraction in DH (step DL), integer in BH (step AH), with the
; fraction carry folded in by ADC. EBX high half = 64K-aligned texture base.
; EBP counts pixels, EDI walks the destination.

bits 32

inner:
        add     ecx,esi                 ; u += du
        mov     al,[ebx]                ; fetch texel
        mov     bl,ch                   ; new u integer
        add     dh,dl                   ; v fraction
        adc     bh,ah                   ; v integer + carry
        mov     [edi],al                ; store pixel
        inc     edi
        dec     ebp
        jnz     inner
