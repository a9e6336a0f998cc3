; listing: fatmap sec. 9 loop A
; source: Byggmastar, fatmap.txt (1996), sec. 9, first inner loop (u and v in two 32-bit registers)
; cpu: pentium
; published: 6 cycles per pixel
; pixels: 1
; branch: none
; note: 32-bit flat; loop-closing branch is the final jnz (taken, predicted); dv is a memory operand ([dv] read every pass); author's figure assumes perfect pairing and no cache misses
;
; u and v are 24.8 fixed point in ECX and EDX; their integer bytes (CH, DH)
; are copied into BL and BH, which index a 256x256 texture aligned on 64K
; (high half of EBX = texture base). EBP counts pixels, EDI walks the
; destination, ESI holds du.

bits 32

dv      equ 0x1000                      ; dword: delta v, 24.8

inner:
        add     edx,[dv]                ; v += dv
        add     ecx,esi                 ; u += du
        mov     al,[ebx]                ; fetch texel
        mov     bl,ch                   ; new u integer
        mov     [edi],al                ; store pixel
        mov     bh,dh                   ; new v integer
        inc     edi
        dec     ebp
        jnz     inner
